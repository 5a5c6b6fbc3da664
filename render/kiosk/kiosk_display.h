#pragma once
// The screen the kiosk shows frames on: a KMS display (fullscreen, page-flipped with vsync, the
// float frame tone-mapped onto it), or a headless EGL context where frames stay offscreen.
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

  // The frame drawn into `target`, shown at `exposure` (KMS), or finished (headless).
  void present(const gpu::OffscreenTarget& target, double exposure);

private:
  std::unique_ptr<gpu::KmsDisplay> kms_;
  std::unique_ptr<gpu::EglContext> headless_;
  std::unique_ptr<gpu::ToneMapper> tonemap_;  // KMS only
  int width_ = 0, height_ = 0;
};

}  // namespace weft
