#pragma once
// A light-probe camera that knows the truth: it photographs a chrome ball standing in a given
// environment map (mirror_ball.h's orthographic camera and orientation), at the requested
// exposure, through a simple sensor — photon shot noise and read noise, clipping at full
// scale — and the camera's response curve with 8-bit quantisation (camera_response.h).
// The scene can change mid-run (set_map: the lamp turns on) and faults can be injected on cue
// (absent, busy, unplugged mid-capture, black or saturated frames). Thread-safe: tests drive it
// from their thread while the probe's worker captures.
#include <cstdint>
#include <mutex>
#include <random>

#include "camera/camera_response.h"
#include "camera/light_probe_source.h"
#include "camera/mirror_ball.h"
#include "lighting/env_map.h"

namespace weft {

struct MockCameraOptions {
  int width = 400;
  int height = 400;
  MirrorBall ball{200.0, 200.0, 190.0};
  CameraCalibration calibration;      // the true camera (what a perfect calibration would measure)
  double full_well_electrons = 6000;  // shot noise: σ = √(electrons)
  double read_noise_electrons = 3;
  double background_radiance = 0.05;  // what the camera sees around the ball
  uint64_t seed = 1;
  std::string name = "mock";
};

enum class MockFrameFault { none, black, saturated };

class MockProbeSource : public LightProbeSource {
public:
  MockProbeSource(const EnvMap& scene, MockCameraOptions options = {});

  std::string name() const override { return "mock camera (" + options_.name + ")"; }
  void open() override;
  void close() override;
  ProbeFrame capture(const ProbeExposure& exposure) override;

  // The scene the ball reflects from the next capture on.
  void set_map(const EnvMap& scene);
  // Fault cues.
  void set_present(bool present);        // absent: open() fails, capture() fails as unplugged
  void set_busy(bool busy);              // another process holds it: open() fails
  void unplug_after(int captures);       // that many more captures succeed, then it is unplugged
  void set_frame_fault(MockFrameFault fault);

  int captures() const;  // successful captures so far
  int opens() const;     // successful opens so far
  const MockCameraOptions& options() const { return options_; }

private:
  void render_ball(const EnvMap& scene);  // caches the scene radiance at every pixel

  MockCameraOptions options_;
  mutable std::mutex mutex_;
  std::vector<glm::vec3> radiance_;  // per pixel, what the sensor sees (before the ball's ρ)
  std::mt19937_64 rng_;
  bool present_ = true, busy_ = false, open_ = false;
  int unplug_countdown_ = -1;
  MockFrameFault frame_fault_ = MockFrameFault::none;
  int captures_ = 0, opens_ = 0;
  uint64_t sequence_ = 0;
};

}  // namespace weft
