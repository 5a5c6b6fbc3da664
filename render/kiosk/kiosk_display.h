#pragma once
// The screen the kiosk shows frames on, which may come and go: a KMS card's connector
// (fullscreen, page-flipped with vsync, the float frame tone-mapped onto it, turned for a
// portrait screen), or none, the frames then staying offscreen.
//
// With a DRM card the GL context lives on the card from the start (kms_display.h), so every GL
// object the kiosk makes survives a screen being plugged, unplugged or swapped: poll() follows
// the kernel's hotplug events (display_watch.h), shows on a screen when one is connected and
// lets it go when it is not. Without a card (display auto) the context is headless (Mesa's
// surfaceless platform); a card appearing later is reported (card_appeared) for the kiosk to
// start again on it, as is its own card disappearing (card_gone): a context cannot move to
// another device.
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace weft {

namespace gpu {
class EglContext;
class KmsDisplay;
class OffscreenTarget;
class ScreenRotation;
class ToneMapper;
}  // namespace gpu
class DisplayWatch;

// Display kms asked for, none found.
class NoDisplayError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct DisplaySettings {
  std::string display = "auto";  // auto (KMS, else headless), kms (a screen at boot or NoDisplayError) or headless
  int width = 640, height = 480;  // the frame while no screen has been shown
  std::string connector;          // --connector: this one only; empty: the first connected
  std::string mode;               // --mode: WxH[@R]; empty: the monitor's preferred
  int rotation = 0;               // --rotation: 0, 90, 180 or 270 degrees clockwise
};

class KioskDisplay {
public:
  // Logs what it opened. Throws NoDisplayError (display kms with no card or no screen),
  // KioskConfigError (--connector names a connector no card has: the message lists those there are).
  explicit KioskDisplay(const DisplaySettings& settings);
  ~KioskDisplay();
  KioskDisplay(const KioskDisplay&) = delete;
  KioskDisplay& operator=(const KioskDisplay&) = delete;

  // The frame to render: the screen's mode (sides swapped for a quarter turn); with no screen,
  // the last screen's, or the settings' size if there has been none.
  int width() const { return width_; }
  int height() const { return height_; }
  bool has_screen() const;
  bool vsynced() const { return has_screen(); }  // present() waits for the screen's refresh
  // Whether screens are followed at all (not display headless).
  bool follows_screens() const { return settings_.display != "headless"; }
  std::string description() const;  // "card0 Virtual-1 1024x768@60", "card0, no screen", "headless"
  std::string name() const;          // "drm:Virtual-1", "headless" or "none"
  std::string connectors() const;    // "card0: HDMI-A-1 (disconnected), …"; "no DRM card"

  enum class Change {
    none,
    shown,          // a screen is shown (again, or another one): present a frame on it
    lost,           // the screen went away: frames stay offscreen
    card_appeared,  // headless for want of a card, and now there is one
    card_gone,      // the card the context lives on is gone
  };
  // Each tick: reads the hotplug events (or, without them, the connectors every 2 s) and follows them.
  Change poll(std::chrono::steady_clock::time_point now);

  // Draws over the tone-mapped frame (the label), given the framebuffer's size; empty: nothing.
  using Overlay = std::function<void(int width, int height)>;

  // The frame drawn into `target`, shown at `exposure` with `overlay` over it on the screen, or
  // finished (no screen: the overlay waits for the screenshot). A screen that fails is let go
  // (the next poll() says lost).
  void present(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay = {});
  // Powers the screen down (the kiosk then draws nothing) or up; logs what it did. A display that
  // cannot (no DPMS, headless) is logged once and keeps showing.
  void set_power(bool on);

  // What the screen shows, upright, as a PNG: `target` through the same tone mapper with `overlay`
  // drawn over it, into an 8-bit frame read back (with or without a screen).
  void screenshot(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay,
                  const std::filesystem::path& file);

private:
  void open_kms();
  bool show(bool probe);  // shows on the chosen connector if there is one; true when it did
  void draw_on_screen(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay);

  DisplaySettings settings_;
  std::unique_ptr<gpu::KmsDisplay> kms_;
  std::unique_ptr<gpu::EglContext> headless_;
  std::unique_ptr<DisplayWatch> watch_;  // null: headless by choice, or no events (then polled)
  std::unique_ptr<gpu::ToneMapper> tonemap_;
  std::unique_ptr<gpu::ScreenRotation> rotation_;  // null: not turned
  int width_ = 0, height_ = 0;
  bool screen_failed_ = false;  // present() let the screen go
  std::chrono::steady_clock::time_point next_look_{};  // without events: the next look at the connectors
  std::optional<std::chrono::steady_clock::time_point> retry_at_;  // a screen that failed is tried again
};

}  // namespace weft
