#include "camera/mock_probe_source.h"

#include <algorithm>
#include <cmath>

namespace weft {

MockProbeSource::MockProbeSource(const EnvMap& scene, MockCameraOptions options)
    : options_(std::move(options)), rng_(options_.seed) {
  render_ball(scene);
}

void MockProbeSource::render_ball(const EnvMap& scene) {
  const int w = options_.width, h = options_.height, n = options_.supersample;
  std::vector<glm::vec3> radiance(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec3 sum(0);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const auto r = options_.ball.reflected_direction(x + (i + 0.5) / n, y + (j + 0.5) / n);
          // The ball's surface reflects ρ of the scene; off the ball the camera sees the room
          // behind, taken as a dim uniform background.
          sum += r ? options_.calibration.ball_reflectance * scene.lookup(*r) : glm::dvec3(options_.background_radiance);
        }
      radiance[static_cast<size_t>(y) * w + x] = glm::vec3(sum / static_cast<double>(n * n));
    }
  std::lock_guard lock(mutex_);
  radiance_ = std::move(radiance);
}

void MockProbeSource::set_map(const EnvMap& scene) { render_ball(scene); }

void MockProbeSource::open() {
  std::lock_guard lock(mutex_);
  if (!present_) throw ProbeError(ProbeFailure::absent, "no camera connected (" + name() + ")");
  if (busy_) throw ProbeError(ProbeFailure::busy, "camera is in use by another process (" + name() + ")");
  if (!open_) ++opens_;
  open_ = true;
}

void MockProbeSource::close() {
  std::lock_guard lock(mutex_);
  open_ = false;
}

ProbeFrame MockProbeSource::capture(const ProbeExposure& exposure) {
  std::lock_guard lock(mutex_);
  if (!present_ || !open_) throw ProbeError(ProbeFailure::disconnected, "camera went away during capture (" + name() + ")");
  if (unplug_countdown_ == 0) {
    present_ = false;
    open_ = false;
    unplug_countdown_ = -1;
    throw ProbeError(ProbeFailure::disconnected, "camera unplugged during capture (" + name() + ")");
  }
  if (unplug_countdown_ > 0) --unplug_countdown_;

  ProbeFrame frame;
  frame.width = options_.width;
  frame.height = options_.height;
  frame.stride = 3 * frame.width;
  frame.exposure = exposure;
  frame.sequence = sequence_++;
  frame.captured = std::chrono::steady_clock::now();
  frame.rgb.assign(static_cast<size_t>(frame.stride) * frame.height, 0);
  if (frame_fault_ == MockFrameFault::saturated) std::fill(frame.rgb.begin(), frame.rgb.end(), 255);
  if (frame_fault_ != MockFrameFault::none) {
    ++captures_;
    return frame;
  }
  const auto& cal = options_.calibration;
  const double to_sensor = cal.radiance_scale * exposure.exposure_s * exposure.analogue_gain;
  const double well = options_.full_well_electrons;
  std::normal_distribution<double> unit(0.0, 1.0);
  for (size_t p = 0; p < radiance_.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      // Electrons collected, their Poisson noise (Gaussian at these counts) and the read noise;
      // the analogue gain amplifies the noise with the signal.
      const double electrons = radiance_[p][c] * to_sensor / exposure.analogue_gain * well;
      const double noisy = electrons + std::sqrt(std::max(electrons, 0.0) + std::pow(options_.read_noise_electrons, 2)) * unit(rng_);
      const double linear = std::clamp(noisy * exposure.analogue_gain / well, 0.0, 1.0);
      frame.rgb[3 * p + c] = cal.response.encode(linear);
    }
  ++captures_;
  return frame;
}

void MockProbeSource::set_present(bool present) {
  std::lock_guard lock(mutex_);
  present_ = present;
  if (!present) open_ = false;
}
void MockProbeSource::set_busy(bool busy) {
  std::lock_guard lock(mutex_);
  busy_ = busy;
}
void MockProbeSource::unplug_after(int captures) {
  std::lock_guard lock(mutex_);
  unplug_countdown_ = captures;
}
void MockProbeSource::set_frame_fault(MockFrameFault fault) {
  std::lock_guard lock(mutex_);
  frame_fault_ = fault;
}
int MockProbeSource::captures() const {
  std::lock_guard lock(mutex_);
  return captures_;
}
int MockProbeSource::opens() const {
  std::lock_guard lock(mutex_);
  return opens_;
}

}  // namespace weft
