#pragma once
// Fullscreen on a bare DRM/KMS card with no compositor (the kmscube pattern: GBM + EGL, page
// flips with vsync), for a screen that may come and go: the card, its GBM device and the EGL
// context are opened once and stay; a connector's scan-out (a GBM surface and its EGL window
// surface) is made when a screen is shown on it and dropped when it goes, the context then
// current without a surface. Which connector and mode: display_choice.h.
#include <memory>
#include <string>
#include <vector>

#include "gpu/display_choice.h"
#include "gpu/egl_context.h"

namespace weft::gpu {

class KmsDisplay {
public:
  // The KMS cards (/dev/dri/card* with connectors), sorted; empty when there is none.
  static std::vector<std::string> cards();

  // Opens `card` (a /dev/dri/card* path), a GBM device on it and an EGL context on that, current
  // without a surface. Throws GpuError naming the card and what failed.
  explicit KmsDisplay(const std::string& card);
  ~KmsDisplay();
  KmsDisplay(const KmsDisplay&) = delete;
  KmsDisplay& operator=(const KmsDisplay&) = delete;

  std::string card() const;  // "card0"
  // The card's connectors. probe: the drivers look again (an EDID read, tens of ms; what a
  // hotplug event calls for), else the kernel's last word. Empty when the card is gone.
  std::vector<DrmConnectorInfo> connectors(bool probe) const;

  // Scan-out on `connector` in `mode` (as connectors() listed them), replacing any screen shown;
  // the mode is set on the first present. Throws GpuError (no CRTC for it, the mode gone, GBM/EGL).
  void show_on(const DrmConnectorInfo& connector, const DrmMode& mode);
  // Lets the screen go: its CRTC off, the surfaces destroyed, the context current without one.
  void let_go();
  bool showing() const;

  int width() const;                // the mode shown; 0 when none
  int height() const;
  std::string description() const;  // "card0 Virtual-1 1024x768@60"; "card0" when none is shown
  std::string connector() const;    // "Virtual-1"; empty when none is shown
  EglContext& context();
  // Swaps the EGL surface and page-flips to it, waiting for the flip (vsync). Throws GpuError
  // when the flip fails or does not complete within a second (the screen or the card gone).
  void present();
  // Powers the screen down or up through the connector's DPMS property. Throws GpuError where the
  // connector has none or the driver refuses.
  void set_power(bool on);
  // The card itself is gone (unplugged: its calls fail with ENODEV), not just its screen.
  bool card_removed() const;

private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace weft::gpu
