#include "kiosk/kiosk_display.h"

#include <exception>

#include "gl/display_target.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/kms_display.h"
#include "gpu/scene_renderer.h"
#include "image/image.h"
#include "kiosk/kiosk_log.h"

namespace weft {

KioskDisplay::KioskDisplay(const std::string& mode, int width, int height) : width_(width), height_(height) {
  if (mode != "headless") {
    try {
      kms_ = std::make_unique<gpu::KmsDisplay>();
      width_ = kms_->width();
      height_ = kms_->height();
      kiosk_log_info("display " + kms_->description());
    } catch (const std::exception& e) {
      if (mode == "kms") throw NoDisplayError(e.what());
      kiosk_log_warning(std::string("no KMS display (") + e.what() + "); running headless");
    }
  }
  if (kms_) {
    tonemap_ = std::make_unique<gpu::ToneMapper>();
  } else {
    headless_ = std::make_unique<gpu::EglContext>(gpu::EglContext::headless());
    kiosk_log_info("headless " + std::to_string(width_) + "x" + std::to_string(height_) + " on " + headless_->renderer());
  }
}

KioskDisplay::~KioskDisplay() = default;

std::string KioskDisplay::description() const { return kms_ ? kms_->description() : "headless"; }

std::string KioskDisplay::name() const { return kms_ ? "drm:" + kms_->connector() : "headless"; }

void KioskDisplay::present(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay) {
  if (kms_) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width_, height_);
    tonemap_->draw(target.colour_texture(), float(exposure));
    if (overlay) overlay(width_, height_);
    kms_->present();
  } else {
    glFinish();
  }
}

void KioskDisplay::set_power(bool on) {
  if (!kms_) {
    kiosk_log_info(std::string("screen ") + (on ? "on" : "off") + " (headless: nothing to power)");
    return;
  }
  try {
    kms_->set_power(on);
    kiosk_log_info(std::string("screen ") + (on ? "on" : "off") + " (DPMS, " + kms_->connector() + ")");
  } catch (const std::exception& e) {
    kiosk_log_warning(e.what());
  }
}

void KioskDisplay::screenshot(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay,
                              const std::filesystem::path& file) {
  if (!tonemap_) tonemap_ = std::make_unique<gpu::ToneMapper>();
  const gpu::DisplayTarget shot(target.width(), target.height());
  shot.bind();
  tonemap_->draw(target.colour_texture(), float(exposure));
  if (overlay) overlay(target.width(), target.height());
  write_png_rgb8(shot.width(), shot.height(), shot.read_rgb(), file);
}

}  // namespace weft
