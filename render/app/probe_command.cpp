// `weft probe`: run the camera light probe for N updates and print the SGs, failures and
// per-update timings. --mock MAP.exr photographs a mirror ball in that map (the truth is known,
// so the irradiance error is printed too); without it, the real camera through libcamera (the
// plugin of package weft-probe-camera).
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "camera/camera_probe_plugin.h"
#include "probe/light_probe_pipeline.h"
#include "probe/mock_probe_source.h"
#include "lighting/fit_error.h"
#include "journal/journal_log.h"

namespace weft {

CommandAction add_probe_command(CLI::App& app) {
  struct Options {
    std::string mock;
    std::string camera;
    int frames = 5;
    int width = 640, height = 480;
    std::vector<double> ball;  // cx cy r
    double radiance_scale = 10.0;
    double reflectance = 0.6;
  };
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand("probe", "Run the camera light probe (mirror ball -> 10 SGs) and print SGs, errors, timings");
  sub->add_option("--mock", o->mock, "Photograph a mirror ball in this EXR map instead of using the camera");
  sub->add_option("--camera", o->camera, "libcamera camera id (default: the first one)");
  sub->add_option("--frames", o->frames, "Updates to run (each is one exposure bracket)")->capture_default_str()->check(CLI::Range(1, 100000));
  sub->add_option("--width,--size", o->width, "Camera frame width (height = 3/4 of it)")->capture_default_str()->check(CLI::Range(64, 8192));
  sub->add_option("--ball", o->ball, "Mirror ball centre x, y and radius in pixels (default: centred, 95 % of the half height)")->expected(3);
  sub->add_option("--radiance-scale", o->radiance_scale, "Calibration k: linear sensor value per unit radiance per second")->capture_default_str();
  sub->add_option("--reflectance", o->reflectance, "Calibration ρ: the chrome ball's reflectance")->capture_default_str();
  return [o]() -> int {
    if (!(o->radiance_scale > 0) || !(o->reflectance > 0 && o->reflectance <= 1))
      throw UsageError("--radiance-scale must be > 0 and --reflectance in (0, 1]");
    LightProbeConfig config;
    config.calibration.radiance_scale = o->radiance_scale;
    config.calibration.ball_reflectance = o->reflectance;
    std::unique_ptr<LightProbeSource> source;
    std::optional<EnvMap> truth;
    int width = o->width, height = o->width * 3 / 4;
    if (!o->mock.empty()) {
      try {
        truth = load_env_map(o->mock, NonFinitePolicy::clamp);
      } catch (const EnvMapError& e) {
        throw UsageError(e.what());
      }
      width = height = 400;
    }
    config.ball = o->ball.size() == 3 ? MirrorBall{o->ball[0], o->ball[1], o->ball[2]}
                                      : MirrorBall{width / 2.0, height / 2.0, 0.95 * height / 2.0};
    if (truth) {
      MockCameraOptions mock;
      mock.width = width;
      mock.height = height;
      mock.ball = config.ball;
      mock.calibration = config.calibration;
      mock.name = o->mock;
      source = std::make_unique<MockProbeSource>(*truth, mock);
    } else {
      LibcameraOptions lc;
      lc.camera_id = o->camera;
      lc.width = width;
      lc.height = height;
      try {
        source = CameraProbePlugin::installed().open(lc);
      } catch (const CameraPluginError& e) {
        log_line("weft probe", LogPriority::error, e.what());
        return 1;
      }
    }
    int failures = 0;
    LightProbeUpdater updater(*source, config, {}, log_probe_line, [] { return Clock::now(); });
    std::printf("%-6s %9s %8s %8s %8s %8s %9s %10s\n", "update", "capture", "merge", "unwrap", "fit", "total", "exposure", "irr_err%");
    for (int i = 0; i < o->frames; ++i) {
      ProbeStepResult r = updater.step();
      if (r == ProbeStepResult::waiting) {
        std::this_thread::sleep_until(updater.retry_at());
        r = updater.step();
      }
      if (r != ProbeStepResult::updated) {
        ++failures;
        std::printf("%-6d failed: %s\n", i + 1, to_string(*updater.failure()));
        continue;
      }
      const auto& t = updater.timings();
      std::printf("%-6d %7.1fms %6.1fms %6.1fms %6.1fms %6.1fms %8.2gs", i + 1, t.capture_ms, t.merge_ms, t.unwrap_ms, t.fit_ms,
                  t.total_ms, updater.shortest_exposure().exposure_s);
      if (truth) std::printf(" %10.2f", 100 * measure_fit_error(*truth, updater.sgs()).irradiance_rmse);
      std::printf("\n");
    }
    if (!updater.has_fit()) {
      log_line("weft probe", LogPriority::warning, "no lighting captured; a kiosk keeps its stored lighting");
      return 1;
    }
    std::printf("\n  k   axis x    axis y    axis z    sharpness  amplitude R  G  B\n");
    int k = 0;
    for (const auto& sg : updater.sgs())
      std::printf("%3d %8.4f  %8.4f  %8.4f  %9.3f   %9.4f %9.4f %9.4f\n", ++k, sg.axis.x, sg.axis.y, sg.axis.z, sg.sharpness,
                  sg.amplitude.r, sg.amplitude.g, sg.amplitude.b);
    return failures > 0 ? 1 : 0;
  };
}

}  // namespace weft
