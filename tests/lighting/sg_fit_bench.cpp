// Benchmark (label bench): the 10-SG fit on every sky of `weft bench --sweep sky` and every
// bundled map (also turned 90°): irradiance error (fit_error.h) of the offline fit (`weft fit`'s
// defaults on the full map) and of the light probe's update (render/probe/light_probe_pipeline.h:
// a 128×64 map, its fit options, warm-started from the previous fit), the CPU time of each, and
// the sharpness range of the fitted lobes. Prints a table; asserts nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "probe/light_probe_pipeline.h"
#include "lighting/env_spec.h"
#include "lighting/fit_error.h"
#include "lighting/sg_fit.h"

using namespace weft;

namespace {
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec;
}

void lambda_range(const SgLighting& sgs, double& lo, double& hi) {
  lo = 1e30, hi = 0;
  for (const auto& g : sgs)
    if (g.amplitude.r + g.amplitude.g + g.amplitude.b > 0) lo = std::min(lo, g.sharpness), hi = std::max(hi, g.sharpness);
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> envs = {"sky:elev=0",  "sky:elev=5",         "sky:elev=10",        "sky:elev=20",
                                   "sky:elev=35", "sky:elev=60",        "sky:elev=10,size=2", "sky:elev=10,size=5",
                                   "sky:elev=10,haze=6", "sky:elev=0,size=2", "sky:elev=0,size=5", "sky:elev=0,haze=6",
                                   "studio",      "courtyard",          "city",               "interior",
                                   "studio@90",   "courtyard@90",       "city@90",            "interior@90"};
  // Arguments: environments to run instead of the list above; --lobes prints each fit's lobes;
  // --weight W and --min-sharpness L set both fits' irradiance weight and λ floor (the study of
  // docs/bench/low_sun/fit_error.md).
  bool print_lobes = false;
  SgFitOptions probe_options = LightProbeConfig{}.fit;
  SgFitOptions fit_options;  // `weft fit`'s defaults
  std::vector<std::string> given;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--lobes") print_lobes = true;
    else if (a == "--weight" && i + 1 < argc) fit_options.irradiance_weight = probe_options.irradiance_weight = std::atof(argv[++i]);
    else if (a == "--min-sharpness" && i + 1 < argc) fit_options.min_sharpness = probe_options.min_sharpness = std::atof(argv[++i]);
    else given.push_back(a);
  }
  if (!given.empty()) envs = given;
  std::printf("irradiance weight %g, min sharpness %g\n", fit_options.irradiance_weight, fit_options.min_sharpness);
  std::printf("CPU ms of this thread; probe: 128x64 map, median of 5 warm updates (cold: the first)\n");
  std::printf("%-22s %8s %8s %9s %9s %8s %8s %9s %9s\n", "env", "fit_err%", "fit_ms", "fit_lmin", "fit_lmax",
              "prb_err%", "prb_ms", "prb_cold", "prb_lmin");
  for (const std::string& env : envs) {
    const EnvMap map = load_env(env, std::string(WEFT_SOURCE_ASSETS) + "/envmaps");
    double t = cpu_ms();
    const SgLighting fit = fit_sgs(map, fit_options);
    const double fit_ms = cpu_ms() - t;
    const double fit_err = measure_fit_error(map, fit).irradiance_rmse;
    double lo, hi;
    lambda_range(fit, lo, hi);

    const EnvMap small = resample(map, 128, 64);
    t = cpu_ms();
    SgLighting sgs = fit_sgs(small, probe_options);
    const double cold_ms = cpu_ms() - t;
    std::vector<double> ms;
    for (int i = 0; i < 5; ++i) {
      t = cpu_ms();
      sgs = fit_sgs(small, probe_options, sgs);
      ms.push_back(cpu_ms() - t);
    }
    std::sort(ms.begin(), ms.end());
    const double probe_err = measure_fit_error(map, sgs).irradiance_rmse;
    double plo, phi;
    lambda_range(sgs, plo, phi);
    std::printf("%-22s %8.2f %8.1f %9.3g %9.4g %8.2f %8.1f %9.1f %9.3g\n", env.c_str(), 100 * fit_err, fit_ms, lo, hi,
                100 * probe_err, ms[2], cold_ms, plo);
    if (print_lobes)
      for (const SgLighting* set : std::initializer_list<const SgLighting*>{&fit, &sgs})
        for (const auto& g : *set)
          std::printf("  %s elev %6.2f azim %7.2f  lambda %8.3g  power %10.4g\n", set == &fit ? "fit  " : "probe",
                      std::asin(g.axis.z) * 180 / M_PI, std::atan2(g.axis.y, g.axis.x) * 180 / M_PI, g.sharpness,
                      (g.amplitude.r + g.amplitude.g + g.amplitude.b) / 3 * 2 * M_PI * -std::expm1(-2 * g.sharpness) / g.sharpness);
    std::fflush(stdout);
  }
}
