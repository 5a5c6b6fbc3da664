#include "gpu/kms_display.h"

#include <fcntl.h>
#include <gbm.h>
#include <poll.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <vector>

namespace weft::gpu {

namespace {

constexpr std::uint32_t kFormat = GBM_FORMAT_XRGB8888;

}  // namespace

struct KmsDisplay::State {
  int fd = -1;
  std::string card;
  gbm_device* gbm = nullptr;
  std::optional<EglContext> egl;
  bool removed = false;  // ENODEV seen

  // The screen shown; connector_id 0 when none.
  std::uint32_t connector_id = 0, crtc_id = 0;
  std::string connector_name;
  drmModeModeInfo mode{};
  gbm_surface* surface = nullptr;
  gbm_bo* front = nullptr;
  bool mode_set = false;
  bool flipped = false;  // the page flip asked for has completed
  // The CRTC as found before the first screen was shown: put back when the kiosk exits.
  drmModeCrtc* saved_crtc = nullptr;
  std::uint32_t saved_connector = 0;

  void note(int err) {
    if (err == ENODEV) removed = true;
  }

  // The window surface and its buffers (the CRTC, if it scans one out, must be off first).
  void drop_surface() {
    if (egl) egl->detach_window();
    if (front && surface) gbm_surface_release_buffer(surface, front);
    front = nullptr;
    if (surface) gbm_surface_destroy(surface);
    surface = nullptr;
  }

  ~State() {
    const bool restore = saved_crtc && connector_id == saved_connector && !removed;
    if (restore)  // put the console (or whatever ran before) back
      drmModeSetCrtc(fd, saved_crtc->crtc_id, saved_crtc->buffer_id, saved_crtc->x, saved_crtc->y, &saved_connector, 1,
                     &saved_crtc->mode);
    else if (connector_id && !removed)
      drmModeSetCrtc(fd, crtc_id, 0, 0, 0, nullptr, 0, nullptr);
    if (saved_crtc) drmModeFreeCrtc(saved_crtc);
    drop_surface();
    egl.reset();
    if (gbm) gbm_device_destroy(gbm);
    if (fd >= 0) close(fd);
  }
};

namespace {

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

DrmMode drm_mode(const drmModeModeInfo& m) {
  return {m.hdisplay, m.vdisplay, int(m.vrefresh), (m.type & DRM_MODE_TYPE_PREFERRED) != 0};
}

// A CRTC that can drive `c`: the one its encoder drives now, else the first its encoders allow.
uint32_t crtc_for(int fd, const drmModeRes* res, const drmModeConnector* c) {
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
  return crtc;
}

}  // namespace

std::vector<std::string> KmsDisplay::cards() {
  std::vector<std::string> paths, found;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator("/dev/dri", ec))
    if (e.path().filename().string().rfind("card", 0) == 0) paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  for (const auto& path : paths) {
    const int fd = open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) continue;
    if (drmModeRes* res = drmModeGetResources(fd)) {  // null: a render-only GPU
      if (res->count_connectors > 0) found.push_back(path);
      drmModeFreeResources(res);
    }
    close(fd);
  }
  return found;
}

KmsDisplay::KmsDisplay(const std::string& card) : s_(std::make_unique<State>()) {
  s_->card = std::filesystem::path(card).filename().string();
  s_->fd = open(card.c_str(), O_RDWR | O_CLOEXEC);
  if (s_->fd < 0) throw GpuError(card + ": " + std::strerror(errno));
  s_->gbm = gbm_create_device(s_->fd);
  if (!s_->gbm) throw GpuError("gbm_create_device failed on " + s_->card);
  s_->egl.emplace(EglContext::on_gbm(s_->gbm, kFormat));
}

KmsDisplay::~KmsDisplay() = default;

std::string KmsDisplay::card() const { return s_->card; }

std::vector<DrmConnectorInfo> KmsDisplay::connectors(bool probe) const {
  std::vector<DrmConnectorInfo> out;
  drmModeRes* res = drmModeGetResources(s_->fd);
  if (!res) {
    s_->note(errno);
    return out;
  }
  for (int i = 0; i < res->count_connectors; ++i) {
    drmModeConnector* c = probe ? drmModeGetConnector(s_->fd, res->connectors[i])
                                : drmModeGetConnectorCurrent(s_->fd, res->connectors[i]);
    if (!c) {
      s_->note(errno);
      continue;
    }
    DrmConnectorInfo info;
    info.id = c->connector_id;
    info.name = connector_name(c->connector_type, c->connector_type_id);
    info.connected = c->connection == DRM_MODE_CONNECTED;
    for (int m = 0; m < c->count_modes; ++m) info.modes.push_back(drm_mode(c->modes[m]));
    out.push_back(std::move(info));
    drmModeFreeConnector(c);
  }
  drmModeFreeResources(res);
  return out;
}

void KmsDisplay::show_on(const DrmConnectorInfo& connector, const DrmMode& mode) {
  let_go();
  State& s = *s_;
  drmModeRes* res = drmModeGetResources(s.fd);
  if (!res) {
    s.note(errno);
    throw GpuError(s.card + ": " + std::strerror(errno));
  }
  drmModeConnector* c = drmModeGetConnectorCurrent(s.fd, connector.id);
  if (!c) {
    drmModeFreeResources(res);
    throw GpuError(s.card + " " + connector.name + ": gone");
  }
  std::optional<drmModeModeInfo> info;
  for (int m = 0; m < c->count_modes && !info; ++m) {
    const DrmMode d = drm_mode(c->modes[m]);
    if (d.width == mode.width && d.height == mode.height && d.refresh_hz == mode.refresh_hz && d.preferred == mode.preferred)
      info = c->modes[m];
  }
  const uint32_t crtc = crtc_for(s.fd, res, c);
  drmModeFreeConnector(c);
  drmModeFreeResources(res);
  if (!info) throw GpuError(s.card + " " + connector.name + " no longer offers " + mode_text(mode));
  if (!crtc) throw GpuError(s.card + " " + connector.name + ": no CRTC can drive it");
  if (!s.saved_crtc) {
    s.saved_crtc = drmModeGetCrtc(s.fd, crtc);
    s.saved_connector = connector.id;
  }
  s.surface = gbm_surface_create(s.gbm, info->hdisplay, info->vdisplay, kFormat, GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
  if (!s.surface) throw GpuError("gbm_surface_create failed for " + s.card + " " + connector.name + " " + mode_text(mode));
  try {
    s.egl->attach_window(s.surface);
  } catch (...) {
    s.drop_surface();
    throw;
  }
  s.connector_id = connector.id;
  s.crtc_id = crtc;
  s.connector_name = connector.name;
  s.mode = *info;
  s.mode_set = false;
}

void KmsDisplay::let_go() {
  State& s = *s_;
  if (!s.connector_id) return;
  // Off before its buffers go: a CRTC must not scan out a framebuffer being freed.
  if (!s.removed && drmModeSetCrtc(s.fd, s.crtc_id, 0, 0, 0, nullptr, 0, nullptr) != 0) s.note(errno);
  s.drop_surface();
  s.connector_id = s.crtc_id = 0;
  s.connector_name.clear();
  s.mode = {};
  s.mode_set = false;
}

bool KmsDisplay::showing() const { return s_->connector_id != 0; }
int KmsDisplay::width() const { return s_->mode.hdisplay; }
int KmsDisplay::height() const { return s_->mode.vdisplay; }
EglContext& KmsDisplay::context() { return *s_->egl; }
std::string KmsDisplay::connector() const { return s_->connector_name; }
bool KmsDisplay::card_removed() const { return s_->removed; }

std::string KmsDisplay::description() const {
  if (!showing()) return s_->card;
  return s_->card + " " + s_->connector_name + " " + mode_text(drm_mode(s_->mode));
}

void KmsDisplay::present() {
  State& s = *s_;
  if (!showing()) throw GpuError("no screen to present on");
  s.egl->swap_buffers();
  gbm_bo* next = gbm_surface_lock_front_buffer(s.surface);
  if (!next) throw GpuError("gbm_surface_lock_front_buffer failed");
  // On a throw below `next` stays locked (a flip may still be queued on it): the caller lets the
  // screen go, which turns the CRTC off before the surface and all its buffers are destroyed.
  const uint32_t fb = framebuffer_for(s.fd, next);
  if (!s.mode_set) {
    if (drmModeSetCrtc(s.fd, s.crtc_id, fb, 0, 0, &s.connector_id, 1, &s.mode) != 0) {
      s.note(errno);
      throw GpuError(std::string("drmModeSetCrtc (mode ") + s.mode.name + "): " + std::strerror(errno));
    }
    s.mode_set = true;
  } else {
    // The flag lives with the card, not on this stack: a flip that timed out may still report later.
    s.flipped = false;
    if (drmModePageFlip(s.fd, s.crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, &s.flipped) != 0) {
      s.note(errno);
      throw GpuError(std::string("drmModePageFlip: ") + std::strerror(errno));
    }
    drmEventContext ev{};
    ev.version = 2;
    ev.page_flip_handler = [](int, unsigned, unsigned, unsigned, void* data) { *static_cast<bool*>(data) = true; };
    while (!s.flipped) {
      pollfd p{s.fd, POLLIN, 0};
      // A flip that never completes must not hang the kiosk: the screen is treated as gone.
      const int r = poll(&p, 1, 1000);
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) throw GpuError("page flip did not complete within 1 s");
      drmHandleEvent(s.fd, &ev);
    }
  }
  if (s.front) gbm_surface_release_buffer(s.surface, s.front);
  s.front = next;
}

void KmsDisplay::set_power(bool on) {
  if (!s_->connector_id) throw GpuError("DPMS: " + s_->card + " shows no screen");
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
