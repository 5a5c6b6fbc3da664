// Benchmark (label bench): capture-to-SGs time per update of the camera light probe against the
// mock camera, per bundled map, and the accuracy it reaches (irradiance error of the fitted SGs
// against the true map, the measure of `weft fit`). Prints a table; asserts nothing about speed.
#include <algorithm>
#include <cstdio>
#include <vector>

#include "probe/light_probe_pipeline.h"
#include "probe/mock_probe_source.h"
#include "lighting/fit_error.h"

using namespace weft;

int main(int argc, char** argv) {
  const int updates = argc > 1 ? std::atoi(argv[1]) : 20;
  std::printf("all times ms, medians over updates 4..N; fit_cpu: the fit's thread CPU time\n");
  std::printf("%-10s %8s %8s %8s %8s %8s %8s %8s %8s %10s\n", "map", "capture", "merge", "unwrap", "smooth", "fit",
              "fit_p90", "fit_cpu", "total", "irr_err%");
  for (const char* name : {"studio", "city", "courtyard", "interior"}) {
    const EnvMap truth = load_env_map(std::string(WEFT_SOURCE_ASSETS) + "/envmaps/" + name + ".exr", NonFinitePolicy::clamp);
    MockCameraOptions mock;
    mock.calibration.radiance_scale = 10.0;
    MockProbeSource source(truth, mock);
    LightProbeConfig config;
    config.ball = mock.ball;
    config.calibration = mock.calibration;
    LightProbeUpdater updater(source, config, {}, [](weft::LogPriority, const std::string& l) { std::fprintf(stderr, "probe: %s\n", l.c_str()); });
    std::vector<ProbeTimings> t;
    for (int i = 0; i < updates; ++i) {
      updater.step();
      if (i >= 3) t.push_back(updater.timings());  // after auto exposure and the cold fit settle
    }
    auto median = [&](double ProbeTimings::*f) {
      std::vector<double> v;
      for (auto& x : t) v.push_back(x.*f);
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    std::vector<double> fit;
    for (auto& x : t) fit.push_back(x.fit_ms);
    std::sort(fit.begin(), fit.end());
    const auto err = measure_fit_error(truth, updater.sgs());
    std::printf("%-10s %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %10.2f   (shortest %.2g s)\n", name,
                median(&ProbeTimings::capture_ms), median(&ProbeTimings::merge_ms), median(&ProbeTimings::unwrap_ms),
                median(&ProbeTimings::smooth_ms), median(&ProbeTimings::fit_ms), fit[fit.size() * 9 / 10],
                median(&ProbeTimings::fit_cpu_ms), median(&ProbeTimings::total_ms), 100 * err.irradiance_rmse,
                updater.shortest_exposure().exposure_s);
  }
}
