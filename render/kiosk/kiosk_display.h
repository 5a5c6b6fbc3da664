#pragma once
// The screen the kiosk shows frames on: a KMS display (fullscreen, page-flipped with vsync, the
// float frame tone-mapped onto it), or a headless EGL context where frames stay offscreen.
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace weft {

namespace gpu {
class EglContext;
class KmsDisplay;
class OffscreenTarget;
class ToneMapper;
}  // namespace gpu

// Display kms asked for, none found.
class NoDisplayError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class KioskDisplay {
public:
  // mode: auto (KMS, else headless with a warning saying why), kms (throws NoDisplayError when
  // there is none) or headless (width × height). Logs what it opened.
  KioskDisplay(const std::string& mode, int width, int height);
  ~KioskDisplay();
  KioskDisplay(const KioskDisplay&) = delete;
  KioskDisplay& operator=(const KioskDisplay&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  bool vsynced() const { return kms_ != nullptr; }  // present() waits for the display's refresh
  std::string description() const;                  // "card0 Virtual-1 1024x768@60", or "headless"
  std::string name() const;                         // "drm:Virtual-1", or "headless"

  // Draws over the tone-mapped frame (the label), given the framebuffer's size; empty: nothing.
  using Overlay = std::function<void(int width, int height)>;

  // The frame drawn into `target`, shown at `exposure` with `overlay` over it (KMS), or finished
  // (headless: the overlay waits for the screenshot).
  void present(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay = {});
  // Powers the screen down (the kiosk then draws nothing) or up; logs what it did. A display that
  // cannot (no DPMS, headless) is logged once and keeps showing.
  void set_power(bool on);

  // What the screen shows, as a PNG: `target` through the same tone mapper with `overlay` drawn
  // over it, into an 8-bit frame read back (on KMS and headless alike).
  void screenshot(const gpu::OffscreenTarget& target, double exposure, const Overlay& overlay,
                  const std::filesystem::path& file);

private:
  std::unique_ptr<gpu::KmsDisplay> kms_;
  std::unique_ptr<gpu::EglContext> headless_;
  std::unique_ptr<gpu::ToneMapper> tonemap_;  // KMS; headless from the first screenshot
  int width_ = 0, height_ = 0;
};

}  // namespace weft
