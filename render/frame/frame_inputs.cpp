#include "frame/frame_inputs.h"

#include <chrono>
#include <iostream>

#include "runtime/scene_bundle.h"
#include "bundle/bundle_reader.h"
#include "lighting/env_spec.h"
#include "lighting/sg_fit.h"
#include "lighting/sg_set_io.h"
#include "reference/environment_samples.h"
#include "scene/scene_fabrics.h"
#include "scene/scene_file.h"
#include "scene/vertex_pass_mesh.h"

namespace weft {

FrameInputs load_frame_inputs(const FrameInputOptions& a) {
  FrameInputs in;
  try {
    in.scene = load_scene_named(a.scene, a.assets, a.fabric);
  } catch (const SceneError& e) {
    throw FrameInputError(e.what());
  }
  for (const std::string& w : in.scene.warnings) std::cerr << "weft render: warning: " << w << "\n";
  for (const auto& obj : in.scene.objects)
    if (obj.repair.degenerate_triangles_dropped > 0)
      std::cerr << "weft render: mesh " << in.scene.name << "/" << obj.name << ": dropped "
                << obj.repair.degenerate_triangles_dropped << " degenerate triangles\n";
  if (!a.bundle.empty()) {
    // The bundle's scene, fabrics and weighting tables; the lighting still comes from the options.
    try {
      const auto reader = bundle::BundleReader::open(a.bundle);
      SceneBundle sb = read_scene_bundle(reader);
      if (!has_shading_data(reader))
        throw FrameInputError("--bundle: " + a.bundle + " has no weighting tables (weft bake without --no-tables)");
      in.shading = std::make_shared<ShadingData>(read_scene_shading_data(reader, sb.scene));
      in.scene = std::move(sb.scene);
    } catch (const bundle::BundleError& e) {
      throw FrameInputError(std::string("--bundle: ") + e.what());
    }
  }
  if (!a.fabric.empty())
    for (auto& obj : in.scene.cloth_objects()) obj.fabric = a.fabric;
  if (a.bundle.empty()) {  // the per-vertex passes' vertices of each dense cloth mesh (a bundle carries its bake's)
    std::cerr << set_pass_meshes(in.scene, "weft render: mesh " + in.scene.name + "/");
  }
  try {
    in.fabrics = load_scene_fabrics(in.scene, a.assets / "fabrics");
  } catch (const FabricError& e) {
    throw FrameInputError(std::string("--fabric: ") + e.what());
  }
  in.env = a.env.empty() ? in.scene.environment : a.env;

  EnvMapRepairs repairs;
  try {
    const auto env_file = env_spec_file(in.env, a.assets / "envmaps");
    if (!env_file.empty() && !std::filesystem::exists(env_file))
      throw FrameInputError("--map: no environment map " + env_file.string());
    in.map = std::make_shared<EnvMap>(load_env(in.env, a.assets / "envmaps", NonFinitePolicy::clamp, &repairs));
  } catch (const EnvSpecError& e) {
    throw FrameInputError(std::string("--map: ") + e.what());
  } catch (const EnvMapError& e) {
    throw FrameInputError(e.what());
  }
  if (repairs.total() > 0)
    std::cerr << "weft render: environment " << in.env << ": clamped " << repairs.nan << " NaN, " << repairs.infinite
              << " infinite and " << repairs.negative << " negative channel values to 0\n";
  return in;
}

ReferenceLighting frame_lighting(const FrameInputs& in, const FrameLightingOptions& a) {
  ReferenceLighting lighting;
  const std::shared_ptr<EnvMap> map = in.map;
  if (a.mode == "map") {
    if (!a.sgs_file.empty()) throw FrameInputError("--sgs: only with --lighting sg");
    const int base = a.map_width;
    lighting.samples = [map, base](int level) { return environment_samples(*map, base << level); };
    lighting.background = [map](const glm::dvec3& d) { return map->lookup(d); };
    lighting.description = "map " + in.env + " as " + std::to_string(base) + "x" + std::to_string(base / 2) +
                           " stratified cells";
    return lighting;
  }
  if (!a.sgs_file.empty()) {
    try {
      lighting.sgs = load_sg_set(a.sgs_file);
    } catch (const SgSetError& e) {
      throw FrameInputError(std::string("--sgs: ") + e.what());
    }
    lighting.description = std::to_string(lighting.sgs.size()) + " SGs from " + a.sgs_file;
  } else {
    const auto t = std::chrono::steady_clock::now();
    SgFitOptions fit;
    fit.count = a.sg_count;
    lighting.sgs = fit_sgs(*map, fit);
    lighting.description = std::to_string(lighting.sgs.size()) + " SGs fitted to " + in.env + " (" +
                           std::to_string(std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count())
                               .substr(0, 4) +
                           " s)";
  }
  lighting.background = [sgs = lighting.sgs](const glm::dvec3& d) { return evaluate(sgs, d); };
  return lighting;
}

}  // namespace weft
