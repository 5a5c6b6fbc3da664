#include "gpu/kms_display.h"

#include <fcntl.h>
#include <gbm.h>
#include <poll.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <algorithm>
#include <optional>
#include <vector>

namespace weft::gpu {

struct KmsDisplay::State {
  int fd = -1;
  std::string card;
  uint32_t connector_id = 0, crtc_id = 0;
  std::string connector_name;
  drmModeModeInfo mode{};
  drmModeCrtc* saved_crtc = nullptr;
  gbm_device* gbm = nullptr;
  gbm_surface* surface = nullptr;
  std::optional<EglContext> egl;
  gbm_bo* front = nullptr;
  bool mode_set = false;

  ~State() {
    egl.reset();
    if (saved_crtc) {  // put the console (or whatever ran before) back
      drmModeSetCrtc(fd, saved_crtc->crtc_id, saved_crtc->buffer_id, saved_crtc->x, saved_crtc->y, &connector_id,
                     1, &saved_crtc->mode);
      drmModeFreeCrtc(saved_crtc);
    }
    if (front && surface) gbm_surface_release_buffer(surface, front);
    if (surface) gbm_surface_destroy(surface);
    if (gbm) gbm_device_destroy(gbm);
    if (fd >= 0) close(fd);
  }
};

namespace {

const char* connector_type_name(uint32_t type) {
  switch (type) {
    case DRM_MODE_CONNECTOR_VGA: return "VGA";
    case DRM_MODE_CONNECTOR_DVII: return "DVI-I";
    case DRM_MODE_CONNECTOR_DVID: return "DVI-D";
    case DRM_MODE_CONNECTOR_HDMIA: return "HDMI-A";
    case DRM_MODE_CONNECTOR_DisplayPort: return "DP";
    case DRM_MODE_CONNECTOR_eDP: return "eDP";
    case DRM_MODE_CONNECTOR_VIRTUAL: return "Virtual";
    case DRM_MODE_CONNECTOR_DSI: return "DSI";
    default: return "Unknown";
  }
}


uint32_t framebuffer_for(int fd, gbm_bo* bo) {
  // The framebuffer id lives with the buffer object so each bo is added once.
  if (void* data = gbm_bo_get_user_data(bo)) return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(data));
  uint32_t fb = 0;
  const uint32_t handles[4] = {gbm_bo_get_handle(bo).u32};
  const uint32_t strides[4] = {gbm_bo_get_stride(bo)};
  const uint32_t offsets[4] = {0};
  if (drmModeAddFB2(fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), gbm_bo_get_format(bo), handles, strides,
                    offsets, &fb, 0) != 0)
    throw GpuError(std::string("drmModeAddFB2: ") + std::strerror(errno));
  gbm_bo_set_user_data(bo, reinterpret_cast<void*>(uintptr_t(fb)), [](gbm_bo* b, void* d) {
    const int dev = gbm_device_get_fd(gbm_bo_get_device(b));
    drmModeRmFB(dev, static_cast<uint32_t>(reinterpret_cast<uintptr_t>(d)));
  });
  return fb;
}

}  // namespace

KmsDisplay::KmsDisplay(const std::string& device) : s_(std::make_unique<State>()) {
  std::vector<std::string> candidates;
  if (!device.empty()) {
    candidates.push_back(device);
  } else {
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator("/dev/dri", ec))
      if (e.path().filename().string().rfind("card", 0) == 0) candidates.push_back(e.path().string());
    std::sort(candidates.begin(), candidates.end());
    if (candidates.empty()) throw GpuError("no DRM device: /dev/dri has no card* (no KMS driver loaded?)");
  }
  std::string why;
  for (const auto& path : candidates) {
    const int fd = open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) {
      why += path + ": " + std::strerror(errno) + "; ";
      continue;
    }
    drmModeRes* res = drmModeGetResources(fd);
    if (!res) {
      why += path + ": not a KMS device; ";
      close(fd);
      continue;
    }
    for (int i = 0; i < res->count_connectors && !s_->connector_id; ++i) {
      drmModeConnector* c = drmModeGetConnector(fd, res->connectors[i]);
      if (!c) continue;
      if (c->connection == DRM_MODE_CONNECTED && c->count_modes > 0) {
        s_->mode = c->modes[0];
        for (int m = 0; m < c->count_modes; ++m)
          if (c->modes[m].type & DRM_MODE_TYPE_PREFERRED) {
            s_->mode = c->modes[m];
            break;
          }
        // A CRTC this connector's encoders can drive; the current one if any.
        uint32_t crtc = 0;
        if (drmModeEncoder* enc = c->encoder_id ? drmModeGetEncoder(fd, c->encoder_id) : nullptr) {
          crtc = enc->crtc_id;
          drmModeFreeEncoder(enc);
        }
        for (int e = 0; e < c->count_encoders && !crtc; ++e) {
          drmModeEncoder* enc = drmModeGetEncoder(fd, c->encoders[e]);
          if (!enc) continue;
          for (int k = 0; k < res->count_crtcs; ++k)
            if (enc->possible_crtcs & (1u << k)) {
              crtc = res->crtcs[k];
              break;
            }
          drmModeFreeEncoder(enc);
        }
        if (crtc) {
          s_->connector_id = c->connector_id;
          s_->crtc_id = crtc;
          s_->connector_name = std::string(connector_type_name(c->connector_type)) + "-" +
                               std::to_string(c->connector_type_id);
        }
      }
      drmModeFreeConnector(c);
    }
    drmModeFreeResources(res);
    if (s_->connector_id) {
      s_->fd = fd;
      s_->card = std::filesystem::path(path).filename().string();
      break;
    }
    why += path + ": no connected display with a mode and a CRTC; ";
    close(fd);
  }
  if (s_->fd < 0) throw GpuError("no usable display: " + why);

  s_->gbm = gbm_create_device(s_->fd);
  if (!s_->gbm) throw GpuError("gbm_create_device failed on " + s_->card);
  const uint32_t format = GBM_FORMAT_XRGB8888;
  s_->surface = gbm_surface_create(s_->gbm, s_->mode.hdisplay, s_->mode.vdisplay, format,
                                   GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
  if (!s_->surface) throw GpuError("gbm_surface_create failed for " + description());
  s_->egl.emplace(EglContext::on_gbm(s_->gbm, s_->surface, format));
  s_->saved_crtc = drmModeGetCrtc(s_->fd, s_->crtc_id);
}

KmsDisplay::~KmsDisplay() = default;

int KmsDisplay::width() const { return s_->mode.hdisplay; }
int KmsDisplay::height() const { return s_->mode.vdisplay; }
EglContext& KmsDisplay::context() { return *s_->egl; }

std::string KmsDisplay::connector() const { return s_->connector_name; }

std::string KmsDisplay::description() const {
  return s_->card + " " + s_->connector_name + " " + std::to_string(width()) + "x" + std::to_string(height()) + "@" +
         std::to_string(s_->mode.vrefresh);
}

void KmsDisplay::present() {
  s_->egl->swap_buffers();
  gbm_bo* next = gbm_surface_lock_front_buffer(s_->surface);
  if (!next) throw GpuError("gbm_surface_lock_front_buffer failed");
  const uint32_t fb = framebuffer_for(s_->fd, next);
  if (!s_->mode_set) {
    if (drmModeSetCrtc(s_->fd, s_->crtc_id, fb, 0, 0, &s_->connector_id, 1, &s_->mode) != 0)
      throw GpuError(std::string("drmModeSetCrtc (mode ") + s_->mode.name + "): " + std::strerror(errno));
    s_->mode_set = true;
  } else {
    bool flipped = false;
    if (drmModePageFlip(s_->fd, s_->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, &flipped) != 0)
      throw GpuError(std::string("drmModePageFlip: ") + std::strerror(errno));
    drmEventContext ev{};
    ev.version = 2;
    ev.page_flip_handler = [](int, unsigned, unsigned, unsigned, void* data) { *static_cast<bool*>(data) = true; };
    while (!flipped) {
      pollfd p{s_->fd, POLLIN, 0};
      // A flip that never completes must not hang the kiosk forever: the watchdog sees it.
      const int r = poll(&p, 1, 1000);
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) throw GpuError("page flip did not complete within 1 s");
      drmHandleEvent(s_->fd, &ev);
    }
  }
  if (s_->front) gbm_surface_release_buffer(s_->surface, s_->front);
  s_->front = next;
}

void KmsDisplay::set_power(bool on) {
  drmModeObjectProperties* props = drmModeObjectGetProperties(s_->fd, s_->connector_id, DRM_MODE_OBJECT_CONNECTOR);
  if (!props) throw GpuError("DPMS: cannot read the properties of " + s_->connector_name);
  uint32_t dpms = 0;
  for (uint32_t i = 0; i < props->count_props && !dpms; ++i)
    if (drmModePropertyRes* p = drmModeGetProperty(s_->fd, props->props[i])) {
      if (std::strcmp(p->name, "DPMS") == 0) dpms = p->prop_id;
      drmModeFreeProperty(p);
    }
  drmModeFreeObjectProperties(props);
  if (!dpms) throw GpuError("DPMS: " + s_->connector_name + " has no DPMS property");
  if (drmModeConnectorSetProperty(s_->fd, s_->connector_id, dpms, on ? DRM_MODE_DPMS_ON : DRM_MODE_DPMS_OFF) != 0)
    throw GpuError(std::string("DPMS ") + (on ? "on" : "off") + " on " + s_->connector_name + ": " + std::strerror(errno));
}

}  // namespace weft::gpu
