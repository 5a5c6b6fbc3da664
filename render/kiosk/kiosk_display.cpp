#include "kiosk/kiosk_display.h"

#include <exception>

#include "gl/display_target.h"
#include "gl/offscreen_target.h"
#include "gpu/display_choice.h"
#include "gpu/egl_context.h"
#include "gpu/kms_display.h"
#include "gpu/scene_renderer.h"
#include "gpu/screen_rotation.h"
#include "image/image.h"
#include "kiosk/display_watch.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/kiosk_log.h"

namespace weft {
namespace {

// Without hotplug events: how often the connectors are looked at (the kernel's last word, no probe).
constexpr auto kLookEvery = std::chrono::seconds(2);
// After a screen failed to present: the wait before it is tried again (unless an event comes first).
constexpr auto kRetryAfterFailure = std::chrono::seconds(5);

}  // namespace

KioskDisplay::KioskDisplay(const DisplaySettings& settings)
    : settings_(settings), width_(settings.width), height_(settings.height) {
  if (follows_screens()) {
    try {
      open_kms();
    } catch (const KioskConfigError&) {
      throw;
    } catch (const std::exception& e) {
      if (settings_.display == "kms") throw NoDisplayError(e.what());
      kiosk_log_warning(std::string("no KMS display (") + e.what() + "); drawing offscreen until a display card appears");
    }
    try {
      watch_ = std::make_unique<DisplayWatch>();
    } catch (const std::exception& e) {
      kiosk_log_warning(std::string("no display hotplug events (") + e.what() + "); looking at the connectors every 2 s");
    }
  }
  if (kms_) {
    if (!show(false)) {
      const std::string why = "no screen connected to " + connectors();
      if (settings_.display == "kms") throw NoDisplayError(why);
      kiosk_log_warning(why + "; drawing offscreen until one is");
    }
  } else {
    headless_ = std::make_unique<gpu::EglContext>(gpu::EglContext::headless());
    kiosk_log_info("headless " + std::to_string(width_) + "x" + std::to_string(height_) + " on " + headless_->renderer());
  }
}

KioskDisplay::~KioskDisplay() = default;

// The card to live on: the one with the connector asked for, else the first with a screen
// connected, else the first that opens (to wait there for one).
void KioskDisplay::open_kms() {
  const std::vector<std::string> cards = gpu::KmsDisplay::cards();
  if (cards.empty()) throw gpu::GpuError("no DRM card: /dev/dri has no card* with connectors (no KMS driver loaded?)");
  std::string why, listed;
  std::unique_ptr<gpu::KmsDisplay> first;
  for (const auto& path : cards) {
    std::unique_ptr<gpu::KmsDisplay> card;
    try {
      card = std::make_unique<gpu::KmsDisplay>(path);
    } catch (const std::exception& e) {
      why += path + ": " + e.what() + "; ";
      continue;
    }
    const std::vector<gpu::DrmConnectorInfo> list = card->connectors(true);
    listed += (listed.empty() ? "" : "; ") + card->card() + ": " + gpu::connector_list(list);
    const bool here = settings_.connector.empty() ? gpu::choose_connector(list, "").has_value()
                                                  : gpu::has_connector(list, settings_.connector);
    if (here) {
      kms_ = std::move(card);
      break;
    }
    if (!first && settings_.connector.empty()) first = std::move(card);
  }
  if (!kms_) kms_ = std::move(first);
  if (!kms_ && !settings_.connector.empty() && !listed.empty())
    throw KioskConfigError("--connector: no connector " + settings_.connector + " (there are " + listed + ")" +
                           (why.empty() ? "" : "; cards that did not open: " + why));
  if (!kms_) throw gpu::GpuError("no usable display card: " + why);
  kms_->context().make_current();  // the cards tried and closed released theirs
  kiosk_log_info("display card " + connectors() + "; drawing with " + kms_->context().renderer());
}

bool KioskDisplay::show(bool probe) {
  const std::vector<gpu::DrmConnectorInfo> list = kms_->connectors(probe);
  const auto i = gpu::choose_connector(list, settings_.connector);
  if (!i) return false;
  const gpu::DrmConnectorInfo& c = list[*i];
  const gpu::ModeChoice m = gpu::choose_mode(c.modes, gpu::parse_mode_request(settings_.mode));
  if (!m.note.empty()) kiosk_log_warning("--mode on " + c.name + ": " + m.note);
  try {
    kms_->show_on(c, c.modes[m.index]);
  } catch (const gpu::GpuError& e) {
    kiosk_log_warning("cannot show on " + kms_->card() + " " + c.name + ": " + e.what());
    return false;
  }
  const gpu::FrameSize f = gpu::rotated_size(kms_->width(), kms_->height(), settings_.rotation);
  width_ = f.width;
  height_ = f.height;
  kiosk_log_info("display " + kms_->description() +
                 (settings_.rotation ? ", turned " + std::to_string(settings_.rotation) + "° (frames " +
                                           std::to_string(width_) + "x" + std::to_string(height_) + ")"
                                     : ""));
  return true;
}

KioskDisplay::Change KioskDisplay::poll(std::chrono::steady_clock::time_point now) {
  if (!follows_screens()) return Change::none;
  const DisplayWatch::Events events = watch_ ? watch_->take() : DisplayWatch::Events{};
  bool look = events.changed;
  if (!watch_ && now >= next_look_) {
    look = true;
    next_look_ = now + kLookEvery;
  }
  if (!kms_) return look && !gpu::KmsDisplay::cards().empty() ? Change::card_appeared : Change::none;
  if (screen_failed_) {  // present() let it go and said why
    screen_failed_ = false;
    retry_at_ = now + kRetryAfterFailure;
    return Change::lost;
  }
  if (retry_at_ && now >= *retry_at_) {
    look = true;
    retry_at_.reset();
  }
  if (!look) return Change::none;
  const std::vector<gpu::DrmConnectorInfo> list = kms_->connectors(events.changed);
  if (kms_->card_removed()) return Change::card_gone;
  const auto i = gpu::choose_connector(list, settings_.connector);
  if (kms_->showing()) {
    // Still there in the mode it would be given now (an event about another connector, or none).
    if (i && list[*i].name == kms_->connector()) {
      const gpu::DrmMode& m = list[*i].modes[gpu::choose_mode(list[*i].modes, gpu::parse_mode_request(settings_.mode)).index];
      if (m.width == kms_->width() && m.height == kms_->height()) return Change::none;
    }
    kiosk_log_warning("display " + kms_->description() + " disconnected");
    kms_->let_go();
    if (i && show(false)) return Change::shown;
    return Change::lost;
  }
  return i && show(false) ? Change::shown : Change::none;
}

bool KioskDisplay::has_screen() const { return kms_ && kms_->showing(); }

std::string KioskDisplay::description() const {
  if (has_screen()) return kms_->description();
  if (kms_) return kms_->card() + ", no screen";
  return follows_screens() ? "offscreen (no display card)" : "headless";
}

std::string KioskDisplay::name() const {
  if (has_screen()) return "drm:" + kms_->connector();
  return follows_screens() ? "none" : "headless";
}

std::string KioskDisplay::connectors() const {
  return kms_ ? kms_->card() + ": " + gpu::connector_list(kms_->connectors(false)) : "no DRM card";
}

void KioskDisplay::present(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay) {
  if (!has_screen()) {
    glFinish();
    return;
  }
  try {
    draw_on_screen(target, exposure, overlay);
    kms_->present();
  } catch (const gpu::GpuError& e) {
    kiosk_log_warning("display " + kms_->description() + ": " + e.what() + "; letting the screen go");
    kms_->let_go();
    screen_failed_ = true;
  }
}

void KioskDisplay::draw_on_screen(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay) {
  if (!tonemap_) tonemap_ = std::make_unique<gpu::ToneMapper>();
  if (settings_.rotation == 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, kms_->width(), kms_->height());
    tonemap_->draw(target.colour_texture(), float(exposure));
    if (overlay) overlay(kms_->width(), kms_->height());
    return;
  }
  // Upright first (the label too), then turned onto the screen.
  if (!rotation_) rotation_ = std::make_unique<gpu::ScreenRotation>(settings_.rotation);
  rotation_->bind_picture(target.width(), target.height());
  tonemap_->draw(target.colour_texture(), float(exposure));
  if (overlay) overlay(target.width(), target.height());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, kms_->width(), kms_->height());
  rotation_->draw_turned();
}

void KioskDisplay::set_power(bool on) {
  if (!kms_ || !kms_->showing()) {
    kiosk_log_info(std::string("screen ") + (on ? "on" : "off") + " (no screen shown: nothing to power)");
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
