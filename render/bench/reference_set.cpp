#include "bench/reference_set.h"

#include <chrono>
#include <iostream>

#include "bench/number_text.h"
#include "bench/stopwatch.h"
#include "reference/environment_samples.h"
#include "reference/scene_render.h"

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
    h.add(o.name).add(o.fabric).add_number(o.material == Material::cloth ? 1 : 0);
    if (o.optical_thickness > 0.0) h.add_number(o.optical_thickness);  // only a sheer's: other keys stay
    h.add_number(o.albedo.r).add_number(o.albedo.g).add_number(o.albedo.b);
    for (const auto* attribute : {&o.mesh.positions, &o.mesh.normals, &o.mesh.warps})
      h.add(std::string_view(reinterpret_cast<const char*>(attribute->data()), attribute->size() * sizeof(glm::dvec3)));
    h.add(std::string_view(reinterpret_cast<const char*>(o.mesh.triangles.data()),
                           o.mesh.triangles.size() * sizeof(o.mesh.triangles[0])));
  }
}

}  // namespace

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
  h.add_number(a.width).add_number(a.height).add_number(a.sg_grid).add_number(a.tangent_samples);
  const auto cache_file = cache_ / (name + "_" + h.hex() + ".ref");
  auto ref = load_reference(cache_file);
  if (ref) {
    ++cached_;
  } else {
    std::cerr << "weft bench: reference " << name << " at " << a.width << "x" << a.height << " ..." << std::flush;
    ReferenceLighting lighting;
    lighting.sgs = c.sgs;
    lighting.background = [sgs = c.sgs](const glm::dvec3& d) { return evaluate(sgs, d); };
    ReferenceRenderOptions opt;
    opt.width = a.width, opt.height = a.height, opt.sg_grid = a.sg_grid, opt.tangent_samples = a.tangent_samples;
    opt.check_convergence = false;
    opt.thin_cloth = thin;
    const auto t = std::chrono::steady_clock::now();
    const ReferenceRenderer rr(c.scene, c.fabrics, lighting, opt);
    const ReferenceRenderResult res = rr.render(0);
    const double secs = seconds_since(t);
    seconds_ += secs;
    ++rendered_;
    std::cerr << " " << fmt(secs) << " s\n";
    ref = CachedReference{res.image, res.kinds};
    store_reference(cache_file, *ref);
  }
  return loaded_.emplace(name, std::move(*ref)).first->second;
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
  h.add_number(a.width).add_number(a.height).add_number(a.tangent_samples);
  const auto cache_file = cache_ / (s.name + "_map_" + h.hex() + ".ref");
  auto ref = load_reference(cache_file);
  if (ref) {
    ++cached_;
    return std::move(*ref);
  }
  std::cerr << "weft bench: map-lit reference " << s.name << " ..." << std::flush;
  ReferenceLighting lighting;
  lighting.samples = [map](int level) { return environment_samples(*map, 128 << level); };
  lighting.background = [map](const glm::dvec3& d) { return map->lookup(d); };
  ReferenceRenderOptions opt;
  opt.width = a.width, opt.height = a.height, opt.tangent_samples = a.tangent_samples;
  opt.check_convergence = false;
  const auto t = std::chrono::steady_clock::now();
  const ReferenceRenderResult res = ReferenceRenderer(s, fabrics, lighting, opt).render(0);
  seconds_ += seconds_since(t);
  ++rendered_;
  std::cerr << " " << fmt(seconds_since(t)) << " s\n";
  CachedReference made{res.image, res.kinds};
  store_reference(cache_file, made);
  return made;
}

}  // namespace weft::bench
