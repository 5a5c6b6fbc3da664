#pragma once
// Fullscreen on a bare DRM/KMS device with no compositor (the kmscube pattern): pick the first
// connected connector and its preferred mode, render through GBM + EGL, page-flip with vsync,
// and put the previous CRTC back on exit.
#include <cstdint>
#include <memory>
#include <string>

#include "gpu/egl_context.h"

namespace weft::gpu {

class KmsDisplay {
public:
  // `device` empty: the first /dev/dri/card* with a connected display. Throws GpuError naming
  // what is missing (no DRM device, no connected connector, no mode, no CRTC).
  explicit KmsDisplay(const std::string& device = "");
  ~KmsDisplay();
  KmsDisplay(const KmsDisplay&) = delete;

  int width() const;
  int height() const;
  std::string description() const;  // "card0 Virtual-1 1024x768@60"
  std::string connector() const;    // "Virtual-1"
  EglContext& context();
  // Swaps the EGL surface and page-flips to it, waiting for the flip (vsync).
  void present();
  // Powers the screen down or up through the connector's DPMS property. Throws GpuError where the
  // connector has none or the driver refuses.
  void set_power(bool on);

private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace weft::gpu
