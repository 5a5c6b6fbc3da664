#include "probe/mock_probe_source.h"

#include <algorithm>
#include <cmath>

namespace weft {

MockProbeSource::MockProbeSource(const EnvMap& scene, MockCameraOptions options)
    : options_(std::move(options)), rng_(options_.seed) {
  render_ball(scene);
}

void MockProbeSource::render_ball(const EnvMap& scene_in) {
  // A camera pixel integrates the light over its footprint, so the ball is rendered by
  // splatting every texel's power (radiance × solid angle) into the pixels around where the
  // ball reflects it, divided by the solid angle a pixel sees there: in the orthographic view a
  // pixel of area 1/r² (ball radii) sees normals over 1/(r²·N·V) sr, and as the reflection
  // doubles the angle from V, dΩ_R = 4·(N·V)·dΩ_N: every pixel sees 4/r² sr.
  // Power is kept exactly, however small the sources (a sun of a few texels).
  // At 2048×1024 a pixel at the ball's centre gathers about a dozen texels, so the splat is even.
  const EnvMap scene = scene_in.width >= 2048 ? scene_in : resample(scene_in, 2048, 1024);
  const int w = options_.width, h = options_.height;
  const MirrorBall& ball = options_.ball;
  const double rho = options_.calibration.ball_reflectance;
  std::vector<glm::dvec3> power(static_cast<size_t>(w) * h, glm::dvec3(0));
  for (int ty = 0; ty < scene.height; ++ty) {
    const double omega = scene.solid_angle(ty);
    for (int tx = 0; tx < scene.width; ++tx) {
      const glm::dvec3 h_vec = scene.direction(tx, ty) + MirrorBall::view;
      const double len = glm::length(h_vec);
      if (len < 1e-9) continue;
      const glm::dvec3 n = h_vec / len;
      const double fx = ball.centre_x + ball.radius * n.x - 0.5, fy = ball.centre_y - ball.radius * n.z - 0.5;
      const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
      const double ax = fx - x0, ay = fy - y0;
      const glm::dvec3 p = rho * omega * glm::dvec3(scene.at(tx, ty));
      const double wts[4] = {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay};
      for (int k = 0; k < 4; ++k) {
        const int x = std::clamp(x0 + (k & 1), 0, w - 1), y = std::clamp(y0 + (k >> 1), 0, h - 1);
        power[static_cast<size_t>(y) * w + x] += wts[k] * p;
      }
    }
  }
  std::vector<glm::vec3> radiance(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double a = (x + 0.5 - ball.centre_x) / ball.radius, b = (y + 0.5 - ball.centre_y) / ball.radius;
      const double c2 = 1.0 - a * a - b * b;
      const size_t i = static_cast<size_t>(y) * w + x;
      // Off the ball the camera sees the room behind, taken as a dim uniform background.
      if (c2 <= 0.0) radiance[i] = glm::vec3(static_cast<float>(options_.background_radiance));
      else radiance[i] = glm::vec3(power[i] / (4.0 / (ball.radius * ball.radius)));
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
