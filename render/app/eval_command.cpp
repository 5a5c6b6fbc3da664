// `weft eval`: one radiance value from a flat, unoccluded swatch (n = +z, warp u = +x,
// weft v = +y) under a few SGs. The contract later checks rely on.
#include <chrono>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "core/cloth_bsdf.h"
#include "bake/tables/table_baker.h"
#include "methods/registry.h"
#include "runtime/paper_tangent_samples.h"
#include "reference/sg_quadrature.h"

namespace weft {

namespace {
struct EvalArgs {
  std::string fabric = "linen_plain";
  std::string view;
  std::vector<std::string> sgs;
  std::string method = "reference";
  int tangent_samples = 64;
  double tolerance = 0.002;
};

// A registered method's C++ evaluation (RuntimeMethod::cpu, as `weft bench`'s stability table
// runs it) at the swatch: table-backed methods bake their small tables on first use, with the
// fabric's tangent samples of the paper's Table 1.
int run_method(const EvalArgs& a, const methods::RuntimeMethod& m, const Fabric& fabric, const dvec3& wo,
               const SgLighting& sgs) {
  const std::array<int, 2> samples = paper_tangent_samples(fabric);
  const ClothBsdf bsdf(fabric, samples);
  const auto t0 = std::chrono::steady_clock::now();
  const methods::CpuShade r = m.cpu(bsdf, SurfaceFrame{}, wo, sgs, table_baker());
  const auto t1 = std::chrono::steady_clock::now();
  nlohmann::ordered_json out;
  out["method"] = a.method;
  out["radiance"] = {r.radiance.r, r.radiance.g, r.radiance.b};
  if (m.see_through) out["alpha"] = r.alpha;
  out["tangent_samples"] = {samples[0], samples[1]};
  out["seconds"] = std::chrono::duration<double>(t1 - t0).count();  // with the tables' bake on first use
  std::cout << out.dump() << "\n";
  return 0;
}

// The methods eval takes: the reference and every registered method with a C++ evaluation.
std::vector<std::string> eval_methods() {
  std::vector<std::string> names{"reference"};
  for (const auto& m : methods::registry())
    if (m.cpu) names.push_back(m.name);
  return names;
}

int run_eval(const EvalArgs& a) {
  const dvec3 wo = parse_direction(a.view, "--view");
  if (wo.z <= 0.0) throw UsageError("--view: direction " + a.view + " is below the surface (z must be > 0)");
  if (a.sgs.empty()) throw UsageError("--sg: give at least one SG");
  SgLighting sgs;
  for (size_t i = 0; i < a.sgs.size(); ++i) sgs.push_back(parse_sg(a.sgs[i], "--sg #" + std::to_string(i + 1)));
  const methods::RuntimeMethod* m = a.method == "reference" ? nullptr : methods::find_method(a.method);
  if (a.method != "reference" && !(m && m->cpu)) {
    std::string names;
    for (const std::string& n : eval_methods()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("--method: '" + a.method + "' is not available for eval (" + names + ")");
  }
  if (a.tangent_samples < 1 || a.tangent_samples > 4096)
    throw UsageError("--tangent-samples: must be in [1, 4096], got " + std::to_string(a.tangent_samples));
  if (!(a.tolerance > 0.0 && a.tolerance < 0.5))
    throw UsageError("--tolerance: must be in (0, 0.5), got " + std::to_string(a.tolerance));

  const Fabric fabric = load_fabric_named(a.fabric, assets_dir() / "fabrics");
  if (m) return run_method(a, *m, fabric, wo, sgs);
  const auto start = std::chrono::steady_clock::now();
  const ClothBsdf bsdf(fabric, a.tangent_samples);
  SgQuadratureOptions opt;
  opt.tolerance = a.tolerance;
  const SgQuadratureResult r = integrate_sg_lighting(bsdf, SurfaceFrame{}, wo, sgs, opt);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  nlohmann::ordered_json out;
  out["method"] = a.method;
  out["radiance"] = {r.radiance.r, r.radiance.g, r.radiance.b};
  out["converged"] = r.converged;
  out["relative_change"] = r.last_change;
  out["tangent_samples"] = a.tangent_samples;
  out["grid"] = {r.polar_cells, 2 * r.polar_cells};
  out["seconds"] = seconds;
  std::cout << out.dump() << "\n";
  if (!r.converged) std::cerr << "weft eval: warning: not converged to " << a.tolerance << " (last change "
                              << r.last_change << ")\n";
  return 0;
}
}  // namespace

CommandAction add_eval_command(CLI::App& app) {
  auto a = std::make_shared<EvalArgs>();
  CLI::App* sub = app.add_subcommand("eval", "One radiance value: a flat swatch (n=+z, warp=+x) under SGs, as JSON");
  sub->add_option("--fabric", a->fabric, "Fabric: a preset name (assets/fabrics/NAME.json) or a .json file")->capture_default_str();
  sub->add_option("--view", a->view, "Direction toward the viewer, x,y,z (normalised; z > 0)")->required();
  sub->add_option("--sg", a->sgs, "An SG light: axis_x,axis_y,axis_z,lambda,r,g,b (repeatable)")->required();
  sub->add_option("--method", a->method, "Method: reference (converged quadrature of docs/design.md §2) or a method's C++ evaluation, unoccluded (" +
                                            [] { std::string n; for (const auto& s : eval_methods()) if (s != "reference") n += (n.empty() ? "" : ", ") + s; return n; }() +
                                            "); table-backed methods bake small tables first")
      ->capture_default_str();
  sub->add_option("--tangent-samples", a->tangent_samples, "Tangent samples per thread N_j")->capture_default_str();
  sub->add_option("--tolerance", a->tolerance, "Convergence: relative change between grid doublings")
      ->capture_default_str();
  return [a] { return run_eval(*a); };
}

}  // namespace weft
