#include "bench/reference_set.h"

#include <chrono>
#include <iostream>

#include "bench/number_text.h"
#include "bench/stopwatch.h"
#include "reference/environment_samples.h"
#include "reference/scene_render.h"
#include "scene/scene_file.h"

namespace weft::bench {

namespace {

// What made the scene: its preset file and the mesh data files scenes read; for a scene loaded
// from a path (a glTF with its buffers, a scene file elsewhere), its camera and objects themselves.
void add_scene_inputs(InputHash& h, const std::filesystem::path& assets, const std::string& scene_arg, const Scene& s) {
  if (!names_scene_file(scene_arg)) {
    add_file(h, assets / "scenes" / (scene_arg + ".json"));
    for (const auto& entry : std::filesystem::directory_iterator(assets / "scenes"))
      if (entry.path().extension() == ".bpt") add_file(h, entry.path());
    return;
  }
  h.add(s.name);
  for (const glm::dvec3& v : {s.camera.position, s.camera.target, s.camera.up})
    h.add_number(v.x).add_number(v.y).add_number(v.z);
  h.add_number(s.camera.fov_deg);
  for (const auto& o : s.objects) {
    h.add(o.name).add(o.fabric).add_number(o.is_cloth() ? 1 : 0);
    if (o.optical_thickness > 0.0) h.add_number(o.optical_thickness);  // only a sheer's: other keys stay
    h.add_number(o.albedo.r).add_number(o.albedo.g).add_number(o.albedo.b);
    if (o.colour) h.add("colour").add_number(o.colour->r).add_number(o.colour->g).add_number(o.colour->b);  // only a coloured object's: other keys stay
    add_mesh(h, o.mesh);
  }
}

}  // namespace

CachedReference ReferenceSet::render(const std::string& name, const std::string& label, const InputHash& inputs,
                                     const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                                     const ReferenceLighting& lighting, ReferenceRenderOptions opt) {
  const BenchOptions& a = options_;
  ReferenceRecord record;
  record.name = name;
  if (a.reference_tolerance > 0.0) {
    TangentConvergenceOptions conv;
    conv.minimum = a.tangent_samples, conv.cap = kReferenceTangentCap, conv.tolerance = a.reference_tolerance;
    InputHash hc = inputs;
    hc.add("tangent-convergence").add_number(conv.minimum).add_number(conv.cap).add_number(conv.tolerance);
    hc.add_number(opt.check_stride);
    const auto choice_file = cache_ / (name + "_nj_" + hc.hex() + ".txt");
    auto choice = load_convergence(choice_file);
    record.tangent_cached = bool(choice);
    if (!choice) {
      std::cerr << "weft bench: " << label << ": tangent samples from " << conv.minimum << " ..." << std::flush;
      choice = converge_tangent_samples(scene, fabrics, lighting, opt, conv);
      seconds_ += choice->seconds;
      for (const auto& step : choice->steps)
        std::cerr << " " << step.samples << " vs " << step.finer << ": " << fmt(100.0 * step.relative_change) << " %;";
      std::cerr << " N_j " << choice->samples << (choice->converged ? "" : " (cap)") << ", " << fmt(choice->seconds)
                << " s\n";
      store_convergence(choice_file, *choice);
    }
    record.tangent = *choice;
  } else {
    record.tangent.samples = a.tangent_samples;
  }
  opt.tangent_samples = record.tangent.samples;
  InputHash h = inputs;
  h.add_number(opt.tangent_samples);
  const auto cache_file = cache_ / (name + "_" + h.hex() + ".ref");
  auto ref = load_reference(cache_file);
  record.image_cached = bool(ref);
  if (ref) {
    ++cached_;
  } else {
    std::cerr << "weft bench: " << label << " at " << opt.width << "x" << opt.height << ", N_j " << opt.tangent_samples
              << " ..." << std::flush;
    opt.check_convergence = false;
    const auto t = std::chrono::steady_clock::now();
    const ReferenceRenderResult res = ReferenceRenderer(scene, fabrics, lighting, opt).render(0);
    record.render_seconds = seconds_since(t);
    seconds_ += record.render_seconds;
    ++rendered_;
    std::cerr << " " << fmt(record.render_seconds) << " s\n";
    ref = CachedReference{res.image, res.kinds};
    store_reference(cache_file, *ref);
  }
  ref->tangent_samples = opt.tangent_samples;
  records_.push_back(record);
  return std::move(*ref);
}

const CachedReference& ReferenceSet::sg_lit(const Case& c, bool thin) {
  const BenchOptions& a = options_;
  const std::string name = c.tag + (thin ? "_thin" : "");
  if (loaded_.count(name)) return loaded_.at(name);
  InputHash h;
  h.add(kReferenceCodeVersion);
  add_scene_inputs(h, a.assets, c.scene_name, c.scene);
  for (const auto& [name, f] : c.fabrics) add_file(h.add(name), fabric_file(name, a.assets / "fabrics"));
  h.add(c.env).add(thin ? "thin" : "opaque");
  for (const auto& g : c.sgs) {
    h.add_number(g.axis.x).add_number(g.axis.y).add_number(g.axis.z).add_number(g.sharpness);
    h.add_number(g.amplitude.r).add_number(g.amplitude.g).add_number(g.amplitude.b);
  }
  h.add_number(a.width).add_number(a.height).add_number(a.sg_grid);
  ReferenceLighting lighting;
  lighting.sgs = c.sgs;
  lighting.background = [sgs = c.sgs](const glm::dvec3& d) { return evaluate(sgs, d); };
  ReferenceRenderOptions opt;
  opt.width = a.width, opt.height = a.height, opt.sg_grid = a.sg_grid;
  opt.thin_cloth = thin;
  return loaded_.emplace(name, render(name, "reference " + name, h, c.scene, c.fabrics, lighting, opt)).first->second;
}

CachedReference ReferenceSet::map_lit(const std::string& scene_arg, const Scene& s,
                                      const std::map<std::string, Fabric>& fabrics,
                                      const std::filesystem::path& env_file, std::shared_ptr<const EnvMap> map) {
  const BenchOptions& a = options_;
  InputHash h;
  h.add(kReferenceCodeVersion);
  add_scene_inputs(h, a.assets, scene_arg, s);
  add_file(h, env_file).add("map128");
  for (const auto& [name, f] : fabrics) add_file(h.add(name), fabric_file(name, a.assets / "fabrics"));
  h.add_number(a.width).add_number(a.height);
  ReferenceLighting lighting;
  lighting.samples = [map](int level) { return environment_samples(*map, 128 << level); };
  lighting.background = [map](const glm::dvec3& d) { return map->lookup(d); };
  ReferenceRenderOptions opt;
  opt.width = a.width, opt.height = a.height;
  return render(s.name + "_map", "map-lit reference " + s.name, h, s, fabrics, lighting, opt);
}

}  // namespace weft::bench
