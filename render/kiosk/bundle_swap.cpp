#include "kiosk/bundle_swap.h"

#include <algorithm>
#include <cstdio>
#include <exception>

#include "bundle/bundle_fallback.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/kiosk_renderer.h"
#include "kiosk/turntable.h"

namespace weft {
namespace {

double ms_since(BundleSwap::Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(BundleSwap::Clock::now() - t).count();
}

}  // namespace

// A bundle read and verified off the render thread, waiting for its GPU resources.
struct BundleSwap::Loaded {
  BundleWatcher::Change change;
  bool unchanged = false;  // the same content as the bundle shown
  std::optional<bundle::BundleReader> reader;  // its bytes, saved as the last good copy once shown
  std::optional<KioskBundle> bundle;
  const methods::RuntimeMethod* method = nullptr;
  double read_ms = 0;
};

// Its renderer, built on the render thread, while a thread prepares its lighting.
struct BundleSwap::Pending {
  BundleWatcher::Change change;
  std::optional<bundle::BundleReader> reader;
  Ready ready;
  std::future<gpu::SceneRenderer::PreparedLighting> lighting;  // after ready's renderer: destroyed (waited for) first
  Clock::time_point lighting_start;
};

BundleSwap::BundleSwap(Options options) : options_(std::move(options)) {
  watcher_ = std::make_unique<BundleWatcher>(options_.bundle);
  kiosk_log_info("watching " + watcher_->directory().string() + " for a new " + watcher_->bundle().filename().string() +
                 " (content updates without a restart)");
  loader_ = std::make_unique<LatestRequestWorker<BundleWatcher::Change, Loaded>>([this](const BundleWatcher::Change& c) {
    const auto t0 = Clock::now();
    Loaded out;
    out.change = c;
    const bundle::BundleReader reader = bundle::BundleReader::read(options_.bundle);
    if (bundle_fingerprint(reader) == shown_fingerprint_.load()) {
      out.unchanged = true;
      return out;
    }
    KioskBundle b = read_kiosk_bundle(reader, options_.method);
    out.method = &kiosk_method(options_.method, b, options_.bundle);
    out.reader = reader;
    out.bundle = std::move(b);
    out.read_ms = ms_since(t0);
    return out;
  });
}

BundleSwap::~BundleSwap() = default;

BundleSwap::Step BundleSwap::poll(const Shown& shown) {
  Step step;
  if (auto change = watcher_->poll()) {
    kiosk_log_info("bundle " + options_.bundle + " changed (" + change->events + "); reading it");
    loader_->request(*change);
  }
  if (pending_) {
    step.ready = finish(shown);
    return step;
  }
  std::optional<Loaded> loaded;
  try {
    loaded = loader_->take();
  } catch (const std::exception& e) {
    refuse(e.what(), shown);
    step.refused = true;
    return step;
  }
  if (!loaded) return step;
  if (loaded->unchanged) {
    kiosk_log_info("bundle " + options_.bundle + " holds the content shown; nothing to swap");
    outcome_ = {std::chrono::system_clock::now(), "unchanged"};
    return step;
  }
  start(std::move(*loaded), shown);
  return step;
}

void BundleSwap::refuse(const std::string& why, const Shown& shown) {
  kiosk_log_error("content update refused: " + why + "; still showing '" + shown.scene + "' from " + shown.file.string());
  outcome_ = {std::chrono::system_clock::now(), "refused: " + why};
}

// The new bundle's GPU resources, built here (the GL context is this thread's), then its lighting
// on a thread: the kiosk keeps drawing the scene shown meanwhile.
void BundleSwap::start(Loaded loaded, const Shown& shown) {
  const auto t0 = Clock::now();
  auto p = std::make_unique<Pending>();
  p->change = loaded.change;
  p->reader = std::move(loaded.reader);
  Ready& r = p->ready;
  r.bundle = std::move(*loaded.bundle);
  r.method = loaded.method;
  r.cloth_fabrics = cloth_fabrics(r.bundle.scene);
  r.room_light = shown.room_light ? *shown.room_light : r.bundle.scene.sgs;
  try {
    r.renderer = make_kiosk_renderer(r.bundle.scene, r.cloth_fabrics, *r.method, r.bundle.shading);
  } catch (const std::exception& e) {
    refuse("bundle " + options_.bundle + ": cannot draw it: " + e.what(), shown);
    return;
  }
  read_ms_ = loaded.read_ms;
  gpu_ms_ = ms_since(t0);
  r.light_version = shown.light_version;
  p->lighting_start = Clock::now();
  const gpu::SceneRenderer* renderer = r.renderer.get();
  p->lighting = std::async(std::launch::async, [renderer, sgs = rotated_about_z(r.room_light, shown.light_rotation_deg)] {
    return renderer->prepare_lighting(sgs);
  });
  pending_ = std::move(p);
}

std::optional<BundleSwap::Ready> BundleSwap::finish(const Shown& shown) {
  if (pending_->lighting.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
  std::unique_ptr<Pending> p = std::move(pending_);
  try {
    p->ready.renderer->set_lighting(p->lighting.get());
  } catch (const std::exception& e) {
    refuse("bundle " + options_.bundle + ": cannot light it: " + e.what(), shown);
    return std::nullopt;
  }
  light_ms_ = ms_since(p->lighting_start);
  shown_fingerprint_ = p->ready.bundle.fingerprint;
  swapped_ = p->change;
  // The bundle shown becomes the last good copy, written (and fsynced) off the render thread.
  if (!options_.state_dir.empty()) {
    if (saving_.valid()) saving_.wait();  // the previous one, rarely still running
    saving_ = std::async(std::launch::async, [this, reader = std::move(*p->reader)] {
      bundle::save_as_last_good(reader, options_.bundle, options_.state_dir, stderr_sink("weft run"));
    });
  }
  return std::move(p->ready);
}

void BundleSwap::log_shown(const SceneBundle& scene, const std::string& method) {
  const double total_ms = ms_since(swapped_->first_event);
  char line[512];
  std::snprintf(line, sizeof line,
                "bundle %s shown %.0f ms after it changed: scene '%s', %zu objects, %zu SGs, %s (read and verified "
                "%.0f ms, GPU resources %.0f ms, lighting %.0f ms)",
                options_.bundle.c_str(), total_ms, scene.scene.name.c_str(), scene.scene.objects.size(), scene.sgs.size(),
                method.c_str(), read_ms_, gpu_ms_, light_ms_);
  kiosk_log_info(line);
  outcome_ = {std::chrono::system_clock::now(), "shown"};
  swapped_.reset();
}

}  // namespace weft
