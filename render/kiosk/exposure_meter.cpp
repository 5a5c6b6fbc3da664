#include "kiosk/exposure_meter.h"

#include <cmath>
#include <vector>

#include <GLES3/gl3.h>
#include "gpu/scene_renderer.h"
#include "image/tone_map.h"

namespace weft {

ExposureMeter::ExposureMeter(double bias_ev, double adapt_seconds) : bias_ev_(bias_ev), adapt_seconds_(adapt_seconds) {}

void ExposureMeter::meter(std::span<const float> rgba) {
  std::vector<glm::dvec3> cloth;
  cloth.reserve(rgba.size() / 4);
  non_finite_pixels_ = 0;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (!gpu::is_cloth_alpha(rgba[i + 3])) continue;
    cloth.emplace_back(rgba[i], rgba[i + 1], rgba[i + 2]);
    if (!std::isfinite(rgba[i]) || !std::isfinite(rgba[i + 1]) || !std::isfinite(rgba[i + 2])) ++non_finite_pixels_;
  }
  cloth_pixels_ = cloth.size();
  target_ = metered_exposure(log_average_luminance(cloth), bias_ev_);
  if (shown_ <= 0.0) shown_ = target_;
  requested_ = false;
}

void ExposureMeter::meter_bound_framebuffer(int width, int height) {
  std::vector<float> rgba(size_t(width) * height * 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
  meter(rgba);
}

void ExposureMeter::ease(Clock::time_point now) {
  shown_ = adapt_exposure(shown_, target_, std::chrono::duration<double>(now - last_ease_).count(), adapt_seconds_);
  last_ease_ = now;
}

// 1 % in log space: below what a frame shows.
bool ExposureMeter::adapting() const { return std::abs(std::log(shown_ / target_)) > 0.01; }

}  // namespace weft
