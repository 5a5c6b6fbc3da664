#pragma once
// The kiosk's exposure (image/tone_map.h): metered on the cloth of a frame (its log-average
// luminance to the key), then eased towards across frames, so a lighting change does not jump.
//
//   meter.request();                 // after a lighting change
//   ... draw ...
//   if (meter.requested()) meter.meter_bound_framebuffer(w, h);
//   meter.ease(now);                 // the exposure shown this frame: meter.shown()
#include <chrono>
#include <cstddef>
#include <span>

namespace weft {

class ExposureMeter {
public:
  using Clock = std::chrono::steady_clock;

  // bias_ev: shifts every metered exposure (+1: twice as bright).
  // adapt_seconds: the time constant of easing towards a new metered exposure.
  ExposureMeter(double bias_ev, double adapt_seconds);

  void request() { requested_ = true; }  // meter the next frame drawn
  bool requested() const { return requested_; }
  // The next metering is shown at once, not eased in from the exposure shown (a new scene).
  void restart() { shown_ = 0.0; }

  // Meters RGBA floats (alpha marks the cloth, gpu::is_cloth_alpha) → target(); the first
  // metering (or the one after restart) is also shown at once. Clears the request.
  void meter(std::span<const float> rgba);
  // The same on the lower-left width × height of the framebuffer bound.
  void meter_bound_framebuffer(int width, int height);

  // Moves shown() towards target() by the time since the previous ease.
  void ease(Clock::time_point now);

  // Of the last metering: the cloth pixels, and those whose radiance was not finite (left out of
  // the average; on screen they are black: a GPU driver that evaluates a shader otherwise).
  size_t cloth_pixels() const { return cloth_pixels_; }
  size_t non_finite_pixels() const { return non_finite_pixels_; }

  double shown() const { return shown_; }    // 0 until the first metering
  double target() const { return target_; }  // 0 until the first metering
  bool adapting() const;                     // shown() still visibly away from target()

private:
  double bias_ev_;
  double adapt_seconds_;
  bool requested_ = false;
  double shown_ = 0.0, target_ = 0.0;
  size_t cloth_pixels_ = 0, non_finite_pixels_ = 0;
  Clock::time_point last_ease_;
};

}  // namespace weft
