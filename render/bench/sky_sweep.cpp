#include "bench/sky_sweep.h"

#include <algorithm>
#include <ctime>
#include <sstream>
#include <map>
#include <stdexcept>

#include "bench/number_text.h"
#include "bench/report.h"
#include "files/atomic_file.h"
#include "lighting/env_spec.h"
#include "lighting/fit_error.h"
#include "lighting/sg_fit.h"
#include "methods/registry.h"

namespace weft::bench {

namespace {
// The sweep's methods: every opaque rung drawn from the weighting tables, in the registry's order
// (low_sun.csv's columns: the first two, then the fit's columns, then the others).
const std::vector<std::string>& sweep_methods() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& m : methods::registry())
      if (m.needs_weighting_tables() && !m.see_through) out.push_back(m.name);
    return out;
  }();
  return names;
}
}  // namespace

std::vector<std::string> sky_sweep_envs(bool smoke) {
  if (smoke) return {"sky:elev=0", "sky:elev=20,size=2", "studio@90"};
  return {"sky:elev=0",         "sky:elev=5",         "sky:elev=10", "sky:elev=20",   "sky:elev=35",
          "sky:elev=60",        "sky:elev=10,size=2", "sky:elev=10,size=5", "sky:elev=10,haze=6",
          "studio@90",          "courtyard@90",       "city@90",     "interior@90"};
}

void apply_sweep(BenchOptions& a) {
  if (a.sweep.empty()) return;
  if (a.sweep != "sky" && a.sweep != "sky-smoke")
    throw InvalidOption("--sweep: expected sky or sky-smoke, got '" + a.sweep + "'");
  const bool smoke = a.sweep == "sky-smoke";
  // Scenes, fabrics, environments and methods given on the command line narrow the preset's (a
  // method the sweep does not list still runs, in results.csv only).
  const BenchOptions defaults;
  a.quick = false;
  if (a.envs == defaults.envs) a.envs = sky_sweep_envs(smoke);
  if (a.methods.empty()) a.methods = sweep_methods();
  a.no_stability = true;
  a.target_error = 0.0;
  a.speed_width = 64, a.speed_height = 48, a.speed_frames = 1;  // the sweep is about accuracy
  if (smoke) {
    a.scenes = {"swatch"};
    a.fabrics = {"linen_plain"};
    a.width = 64, a.height = 48;
    a.sg_grid = 4, a.tangent_samples = 8, a.reference_tolerance = 0.0;  // a smoke run: N_j fixed
    a.bake_grid = 12;
  } else {
    if (a.scenes == defaults.scenes) a.scenes = {"pillow", "drape"};
    if (a.fabrics == defaults.fabrics) a.fabrics = {"linen_plain", "polyester_satin_charmeuse"};
    // The accuracy size stays --width x --height (320x240 by default).
  }
}

FitCondition measure_fit_condition(const BenchOptions& a, const std::string& env) {
  FitCondition f;
  f.env = env;
  const EnvMap map = load_env(env, a.assets / "envmaps");
  SgFitOptions bench_fit;
  bench_fit.count = a.sg_count;
  f.irradiance_error = measure_fit_error(map, fit_sgs(map, bench_fit)).irradiance_rmse;
  // The light probe's settings (render/probe/light_probe_pipeline.h): grid 64, 8 iterations,
  // warm-started from the last fit.
  SgFitOptions probe{a.sg_count, 64, 1.0, 1000.0, 8};
  SgLighting sgs = fit_sgs(map, probe);
  // CPU time of this thread: the fit is single-threaded, and on a shared machine wall time
  // counts the other processes too.
  auto cpu_ms = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec;
  };
  std::vector<double> ms;
  for (int i = 0; i < 3; ++i) {
    const double t = cpu_ms();
    sgs = fit_sgs(map, probe, sgs);
    ms.push_back(cpu_ms() - t);
  }
  std::sort(ms.begin(), ms.end());
  f.probe_update_ms = ms[1];
  f.probe_irradiance_error = measure_fit_error(map, sgs).irradiance_rmse;
  return f;
}

namespace {

std::string quoted(const std::string& s) { return s.find(',') == std::string::npos ? s : "\"" + s + "\""; }

double median(std::vector<double> v) {
  if (v.empty()) return -1.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

void write_sky_sweep(const std::filesystem::path& out, const BenchOptions& a, const BenchResults& res) {
  if (a.sweep.empty()) return;
  std::map<std::string, FitCondition> fits;
  for (const auto& env : a.envs) fits.emplace(env, measure_fit_condition(a, env));

  struct Case {
    std::string scene, fabric, env;
    std::vector<double> rmse;  // by sweep_methods(); −1: not run
    int reference_samples = 0;
  };
  const std::vector<std::string>& sweep = sweep_methods();
  const size_t count = sweep.size();
  std::vector<Case> cases;
  for (const auto& r : res.rows) {
    const auto m = std::find(sweep.begin(), sweep.end(), r.method);
    if (m == sweep.end()) continue;
    auto it = std::find_if(cases.begin(), cases.end(),
                           [&](const Case& c) { return c.scene == r.scene && c.fabric == r.fabric && c.env == r.env; });
    if (it == cases.end()) {
      it = cases.insert(cases.end(), Case{r.scene, r.fabric, r.env, std::vector<double>(count, -1.0)});
    }
    it->rmse[size_t(m - sweep.begin())] = r.rmse;
    it->reference_samples = r.reference_tangent_samples;
  }

  std::ostringstream csv;
  csv << "scene,fabric,env," << sweep[0] << "_rmse," << sweep[1]
      << "_rmse,fit_irradiance_error,probe_irradiance_error,probe_update_ms,reference_tangent_samples";
  for (size_t i = 2; i < count; ++i) csv << "," << sweep[i] << "_rmse";
  csv << "\n";
  for (const auto& c : cases) {
    const FitCondition& f = fits.at(c.env);
    csv << c.scene << "," << c.fabric << "," << quoted(c.env) << "," << fmt(c.rmse[0], 4) << "," << fmt(c.rmse[1], 4)
        << "," << fmt(f.irradiance_error, 4) << "," << fmt(f.probe_irradiance_error, 4) << ","
        << fmt(f.probe_update_ms, 4) << "," << c.reference_samples;
    for (size_t i = 2; i < count; ++i) csv << "," << fmt(c.rmse[i], 4);
    csv << "\n";
  }
  write_file_atomically(out / "low_sun.csv", csv.view());

  double fit_worst = 0.0, probe_worst = 0.0, probe_ms_worst = 0.0;
  for (const auto& [env, f] : fits) {
    fit_worst = std::max(fit_worst, f.irradiance_error);
    probe_worst = std::max(probe_worst, f.probe_irradiance_error);
    probe_ms_worst = std::max(probe_ms_worst, f.probe_update_ms);
  }
  std::ostringstream md;
  md << "# Low suns and turned maps (`weft bench --sweep " << a.sweep << "`)\n\n"
     << "Relative RMSE over the cloth pixels at " << a.width << "x" << a.height
     << " against the reference under the same " << a.sg_count << " fitted SGs (SG grid " << a.sg_grid << ", "
     << reference_samples_text(a) << "); the fit's irradiance error "
     << "(fit_error.h) with the bench's fit and with the probe's warm update (grid 64, 8 iterations).\n\n"
     << "Summary: ";
  for (size_t i = 0; i < count; ++i) {
    std::vector<double> run;
    for (const auto& c : cases)
      if (c.rmse[i] >= 0) run.push_back(c.rmse[i]);
    md << sweep[i] << " worst " << fmt(run.empty() ? -1 : *std::max_element(run.begin(), run.end()))
       << ", median " << fmt(median(run)) << "; ";
  }
  md << "fit irradiance error worst " << fmt(fit_worst) << " (probe update " << fmt(probe_worst) << ", at most "
     << fmt(probe_ms_worst) << " ms of CPU time per update).\n\n| scene | fabric | env | ";
  for (const std::string& m : sweep) md << m << " | ";
  md << "fit irradiance error | probe update: error / CPU ms | reference N_j |\n|---|---|---|";
  for (size_t i = 0; i < count; ++i) md << "---|";
  md << "---|---|---|\n";
  for (const auto& c : cases) {
    const FitCondition& f = fits.at(c.env);
    md << "| " << c.scene << " | " << c.fabric << " | `" << c.env << "` | ";
    for (double e : c.rmse) md << fmt(e) << " | ";
    md << fmt(f.irradiance_error) << " | " << fmt(f.probe_irradiance_error) << " / " << fmt(f.probe_update_ms) << " | "
       << c.reference_samples << " |\n";
  }
  md << "\n## References\n\nN_j: tangent samples per thread; doublings: the check subset's cloth change from N to "
        "2N; times on this run's machine (cached: from an earlier run).\n\n"
     << "| reference | N_j | doublings | choice: s | render: s |\n|---|---|---|---|---|\n";
  for (const auto& r : res.references) {
    std::string steps;
    for (const auto& s : r.tangent.steps)
      steps += (steps.empty() ? "" : ", ") + std::to_string(s.samples) + "→" + std::to_string(s.finer) + ": " +
               fmt(100.0 * s.relative_change) + " %";
    md << "| " << r.name << " | " << r.tangent.samples << (r.tangent.steps.empty() || r.tangent.converged ? "" : " (cap)")
       << " | " << (steps.empty() ? "fixed" : steps) << " | "
       << (r.tangent.steps.empty() ? "" : r.tangent_cached ? "cached (" + fmt(r.tangent.seconds) + ")" : fmt(r.tangent.seconds))
       << " | " << (r.image_cached ? "cached" : fmt(r.render_seconds)) << " |\n";
  }
  write_file_atomically(out / "low_sun.md", md.view());
}

}  // namespace weft::bench
