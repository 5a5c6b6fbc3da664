#include "camera/libcamera_probe_source.h"

#include <sys/mman.h>

#include <cstdlib>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>

#include <libcamera/camera.h>
#include <libcamera/camera_manager.h>
#include <libcamera/control_ids.h>
#include <libcamera/formats.h>
#include <libcamera/framebuffer_allocator.h>
#include <libcamera/logging.h>
#include <libcamera/request.h>
#include <libcamera/stream.h>

namespace weft {

namespace lc = libcamera;

namespace {

// libcamera's own INFO/WARN chatter (e.g. "No IPA found") would drown the kiosk's log; keep its errors.
void quiet_libcamera() {
  static std::once_flag once;
  std::call_once(once, [] {
    setenv("LIBCAMERA_LOG_LEVELS", "*:ERROR", 0);  // an operator's own setting wins
    lc::logSetLevel("*", "ERROR");
  });
}

// Byte offsets of R, G, B within one pixel, and bytes per pixel, for the formats we accept
// (DRM fourcc naming: RGB888 is B,G,R in memory).
struct PixelLayout {
  int r, g, b, bytes;
};
std::optional<PixelLayout> layout_of(const lc::PixelFormat& f) {
  if (f == lc::formats::BGR888) return PixelLayout{0, 1, 2, 3};
  if (f == lc::formats::RGB888) return PixelLayout{2, 1, 0, 3};
  if (f == lc::formats::XBGR8888) return PixelLayout{0, 1, 2, 4};
  if (f == lc::formats::XRGB8888) return PixelLayout{2, 1, 0, 4};
  return std::nullopt;
}

}  // namespace

struct LibcameraProbeSource::State {
  std::unique_ptr<lc::CameraManager> manager;
  std::shared_ptr<lc::Camera> camera;
  bool acquired = false, started = false;
  std::unique_ptr<lc::CameraConfiguration> config;
  lc::Stream* stream = nullptr;
  std::unique_ptr<lc::FrameBufferAllocator> allocator;
  std::unique_ptr<lc::Request> request;
  void* mapped = MAP_FAILED;
  size_t mapped_length = 0;
  size_t plane_offset = 0;
  PixelLayout layout{};
  std::mutex mutex;
  std::condition_variable done;
  bool completed = false;
  std::atomic<bool> disconnected{false};
  uint64_t sequence = 0;

  void on_request(lc::Request*) {
    {
      std::lock_guard lock(mutex);
      completed = true;
    }
    done.notify_all();
  }
  void on_disconnect() {
    disconnected = true;
    done.notify_all();
  }

  ~State() {
    if (camera && started) camera->stop();
    if (camera) {
      camera->requestCompleted.disconnect(this);
      camera->disconnected.disconnect(this);
    }
    request.reset();
    if (mapped != MAP_FAILED) munmap(mapped, mapped_length);
    allocator.reset();
    if (camera && acquired) camera->release();
    camera.reset();
    if (manager) manager->stop();
  }
};

LibcameraProbeSource::LibcameraProbeSource(LibcameraOptions options) : options_(std::move(options)) {}
LibcameraProbeSource::~LibcameraProbeSource() { close(); }

std::string LibcameraProbeSource::name() const {
  if (state_ && state_->camera) return "libcamera " + state_->camera->id();
  return "libcamera " + (options_.camera_id.empty() ? std::string("(first camera)") : options_.camera_id);
}

std::vector<std::string> LibcameraProbeSource::list_cameras() {
  quiet_libcamera();
  lc::CameraManager manager;
  if (manager.start() < 0) return {};
  std::vector<std::string> ids;
  for (const auto& c : manager.cameras()) ids.push_back(c->id());
  manager.stop();
  return ids;
}

void LibcameraProbeSource::open() {
  if (state_) return;
  quiet_libcamera();
  auto s = std::make_unique<State>();
  s->manager = std::make_unique<lc::CameraManager>();
  if (int ret = s->manager->start(); ret < 0) {
    s->manager.reset();
    throw ProbeError(ProbeFailure::absent, std::string("libcamera could not start its camera manager: ") + std::strerror(-ret));
  }
  const auto cameras = s->manager->cameras();
  if (cameras.empty()) throw ProbeError(ProbeFailure::absent, "no camera found (libcamera lists none)");
  if (options_.camera_id.empty()) s->camera = cameras.front();
  else s->camera = s->manager->get(options_.camera_id);
  if (!s->camera) {
    std::string ids;
    for (const auto& c : cameras) ids += (ids.empty() ? "" : ", ") + c->id();
    throw ProbeError(ProbeFailure::absent, "camera '" + options_.camera_id + "' not found (libcamera lists: " + ids + ")");
  }
  if (int ret = s->camera->acquire(); ret < 0) {
    if (ret == -EBUSY) throw ProbeError(ProbeFailure::busy, "camera " + s->camera->id() + " is in use by another process");
    throw ProbeError(ProbeFailure::config, "cannot acquire camera " + s->camera->id() + ": " + std::strerror(-ret));
  }
  s->acquired = true;

  s->config = s->camera->generateConfiguration({lc::StreamRole::StillCapture});
  if (!s->config || s->config->empty()) throw ProbeError(ProbeFailure::config, "camera offers no still-capture stream");
  lc::StreamConfiguration& cfg = s->config->at(0);
  cfg.pixelFormat = lc::formats::BGR888;
  cfg.size = {static_cast<unsigned>(options_.width), static_cast<unsigned>(options_.height)};
  cfg.bufferCount = 1;
  if (s->config->validate() == lc::CameraConfiguration::Invalid)
    throw ProbeError(ProbeFailure::config, "camera rejects an RGB still stream of " + std::to_string(options_.width) + "×" +
                                               std::to_string(options_.height));
  const auto layout = layout_of(cfg.pixelFormat);
  if (!layout) throw ProbeError(ProbeFailure::config, "camera offers " + cfg.pixelFormat.toString() + ", not 8-bit RGB");
  s->layout = *layout;
  if (int ret = s->camera->configure(s->config.get()); ret < 0)
    throw ProbeError(ProbeFailure::config, std::string("camera configuration failed: ") + std::strerror(-ret));
  s->stream = cfg.stream();

  s->allocator = std::make_unique<lc::FrameBufferAllocator>(s->camera);
  if (s->allocator->allocate(s->stream) < 0 || s->allocator->buffers(s->stream).empty())
    throw ProbeError(ProbeFailure::config, "cannot allocate camera buffers");
  lc::FrameBuffer* buffer = s->allocator->buffers(s->stream).front().get();
  const auto& plane = buffer->planes().front();
  s->plane_offset = plane.offset == lc::FrameBuffer::Plane::kInvalidOffset ? 0 : plane.offset;
  s->mapped_length = s->plane_offset + plane.length;
  s->mapped = mmap(nullptr, s->mapped_length, PROT_READ, MAP_SHARED, plane.fd.get(), 0);
  if (s->mapped == MAP_FAILED) throw ProbeError(ProbeFailure::config, std::string("cannot map camera buffer: ") + std::strerror(errno));

  s->request = s->camera->createRequest();
  if (!s->request || s->request->addBuffer(s->stream, buffer) < 0)
    throw ProbeError(ProbeFailure::config, "cannot create a capture request");
  s->camera->requestCompleted.connect(s.get(), &State::on_request);
  s->camera->disconnected.connect(s.get(), &State::on_disconnect);

  lc::ControlList start_controls;
  start_controls.set(lc::controls::AeEnable, false);
  if (int ret = s->camera->start(&start_controls); ret < 0)
    throw ProbeError(ProbeFailure::config, std::string("camera does not start: ") + std::strerror(-ret));
  s->started = true;
  state_ = std::move(s);
}

void LibcameraProbeSource::close() { state_.reset(); }

ProbeFrame LibcameraProbeSource::capture(const ProbeExposure& exposure) {
  if (!state_) throw ProbeError(ProbeFailure::disconnected, "capture on a camera that is not open");
  State& s = *state_;
  const int32_t exposure_us = static_cast<int32_t>(std::lround(exposure.exposure_s * 1e6));
  for (int attempt = 0;; ++attempt) {
    if (s.disconnected) throw ProbeError(ProbeFailure::disconnected, "camera " + s.camera->id() + " disconnected");
    s.request->reuse(lc::Request::ReuseBuffers);
    s.request->controls().set(lc::controls::AeEnable, false);
    s.request->controls().set(lc::controls::ExposureTime, exposure_us);
    s.request->controls().set(lc::controls::AnalogueGain, static_cast<float>(exposure.analogue_gain));
    {
      std::lock_guard lock(s.mutex);
      s.completed = false;
    }
    if (int ret = s.camera->queueRequest(s.request.get()); ret < 0)
      throw ProbeError(ret == -ENODEV ? ProbeFailure::disconnected : ProbeFailure::config,
                       std::string("camera refuses the capture request: ") + std::strerror(-ret));
    {
      std::unique_lock lock(s.mutex);
      if (!s.done.wait_for(lock, options_.timeout, [&] { return s.completed || s.disconnected.load(); }))
        throw ProbeError(ProbeFailure::timeout, "no frame from camera " + s.camera->id() + " within " +
                                                    std::to_string(options_.timeout.count()) + " ms");
    }
    if (s.disconnected || s.request->status() == lc::Request::RequestCancelled)
      throw ProbeError(ProbeFailure::disconnected, "camera " + s.camera->id() + " went away during capture");

    const auto& meta = s.request->metadata();
    ProbeExposure used = exposure;
    if (auto t = meta.get(lc::controls::ExposureTime)) used.exposure_s = *t * 1e-6;
    if (auto g = meta.get(lc::controls::AnalogueGain)) used.analogue_gain = *g;
    const double ratio = used.exposure_s * used.analogue_gain / (exposure.exposure_s * exposure.analogue_gain);
    if (std::abs(ratio - 1.0) > 0.05 && attempt < options_.settle_retries) continue;

    const lc::StreamConfiguration& cfg = s.config->at(0);
    ProbeFrame frame;
    frame.width = static_cast<int>(cfg.size.width);
    frame.height = static_cast<int>(cfg.size.height);
    frame.stride = 3 * frame.width;
    frame.exposure = used;
    frame.sequence = s.sequence++;
    frame.captured = std::chrono::steady_clock::now();
    frame.rgb.resize(static_cast<size_t>(frame.stride) * frame.height);
    if (s.plane_offset + static_cast<size_t>(cfg.stride) * frame.height > s.mapped_length)
      throw ProbeError(ProbeFailure::bad_frame, "camera buffer smaller than its format says");
    const auto* base = static_cast<const uint8_t*>(s.mapped) + s.plane_offset;
    for (int y = 0; y < frame.height; ++y) {
      const uint8_t* src = base + static_cast<size_t>(y) * cfg.stride;
      uint8_t* dst = frame.rgb.data() + static_cast<size_t>(y) * frame.stride;
      for (int x = 0; x < frame.width; ++x, src += s.layout.bytes, dst += 3) {
        dst[0] = src[s.layout.r];
        dst[1] = src[s.layout.g];
        dst[2] = src[s.layout.b];
      }
    }
    return frame;
  }
}

}  // namespace weft
