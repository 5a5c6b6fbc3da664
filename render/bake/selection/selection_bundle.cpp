#include "bake/selection/selection_bundle.h"

#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "bake/writers/bundle_fabrics.h"
#include "bake/writers/shading_data_writer.h"
#include "bake/selection/rung_choice.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"
#include "scene/mesh_vertex_order.h"
#include "scene/vertex_pass_mesh.h"

namespace weft {

std::string selection_json(const SceneSelection& s, const SceneSelectionOptions& o) {
  const SceneSetting& c = s.chosen.setting;
  const SelectionKnobs& k = o.knobs;
  nlohmann::json tangent = nlohmann::json::object();
  for (const auto& [preset, t] : s.data.tables) tangent[preset] = {t.tangent_samples[0], t.tangent_samples[1]};
  nlohmann::json j = {{"target_error", s.target},
                      {"reached", s.reached},
                      {"error", s.chosen.error},
                      {"view_errors", s.chosen.view_errors},
                      {"frame_ms", s.chosen.ms},
                      {"bytes", s.chosen.bytes},
                      {"method", s.method},
                      {"setting", s.description},
                      {"tangent_samples", tangent},
                      {"lambda_levels", s.data.tables.empty() ? 0 : s.data.tables.begin()->second.level_count()},
                      {"svd_error", k.svd_errors[c.svd]},
                      {"sg_count", s.chosen.sg_count},
                      {"subdivision", s.subdivision},
                      {"views", {{"count", o.views.count}, {"spread_deg", o.views.spread_deg},
                                 {"width", o.views.width}, {"height", o.views.height}}},
                      {"settings_measured", s.tried.size()}};
  if (!s.data.visibility.empty()) {
    j["sdf_resolution"] = k.sdf_resolutions[c.sdf];
    j["pca_rms_error"] = k.pca_errors[c.pca];
  }
  return j.dump();
}

std::string selection_summary(const SceneSelection& s, const SceneSelectionOptions& o) {
  std::string views, out;
  char buf[400];
  for (double e : s.chosen.view_errors) {
    std::snprintf(buf, sizeof buf, "%s%.4f", views.empty() ? "" : " / ", e);
    views += buf;
  }
  std::snprintf(buf, sizeof buf, "%-14s %s\n", "setting", s.description.c_str());
  out += buf;
  std::snprintf(buf, sizeof buf, "%-14s %.4f (views %s) against target %g: %s\n", "image error", s.chosen.error,
                views.c_str(), s.target,
                s.reached ? "reached" : "UNREACHABLE with these knobs; took the closest setting");
  out += buf;
  std::snprintf(buf, sizeof buf, "%-14s %.2f MB (tables + visibility + kappa + mesh sections subdivision adds)\n", "bytes", s.chosen.bytes / 1e6);
  out += buf;
  if (s.paper) {
    std::snprintf(buf, sizeof buf, "%-14s %s: error %.4f, %.2f MB, %.1f ms\n", "paper setting",
                  describe(s.paper->setting, o.knobs, !s.data.visibility.empty()).c_str(), s.paper->error,
                  s.paper->bytes / 1e6, s.paper->ms);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "%-14s %.1f ms per %dx%d frame (this machine); modelled cost %.3g (pixel x SG x sample steps at 640x480)\n",
                "frame", s.chosen.ms, o.views.width, o.views.height, s.chosen.work);
  out += buf;
  std::snprintf(buf, sizeof buf, "%-14s %zu settings measured on %zu views (%d references rendered, %d cached), %.1f s\n",
                "search", s.tried.size(), s.chosen.view_errors.size(), s.references_rendered, s.references_cached,
                s.seconds);
  return out + buf;
}

void add_selection_sections(bundle::BundleWriter& writer, const SceneSelection& s, const SceneSelectionOptions& o) {
  add_shading_data_sections(writer, s.data);
  writer.add_json(kSelectionSection, selection_json(s, o));
}

}  // namespace weft

namespace weft {

SceneSelection select_for_bundle(const Scene& scene, const std::map<std::string, std::string>& fabric_texts,
                                 const SgLighting& sgs, const SceneSelectionOptions& o,
                                 const std::filesystem::path& sg_map) {
  const std::map<std::string, Fabric> fabrics = cloth_fabrics(scene, fabric_texts);
  SceneSelectionOptions with = o;
  if (with.cache.empty()) with.cache = default_reference_cache();
  if (!with.log) with.log = [](const std::string& line) { std::fprintf(stderr, "  select: %s\n", line.c_str()); };
  SgLighting lighting = sgs;
  if (!sg_map.empty()) {
    const auto map = std::make_shared<const EnvMap>(load_env_map(sg_map, NonFinitePolicy::clamp));
    with.knobs.sg_counts = kBakeSgCounts;
    with.fit = [map](int count) {
      SgFitOptions fit;
      fit.count = count;
      return fit_sgs(*map, fit);
    };
    lighting = with.fit(kReferenceSgCount);
  }
  SceneSelection s = select_scene_settings(scene, fabrics, fabric_texts, lighting, with);
  std::fputs(selection_summary(s, with).c_str(), stderr);
  return s;
}

std::string add_selected_bundle(bundle::BundleWriter& writer, SceneBundleInput& in, const SceneSelectionOptions& o,
                                const std::filesystem::path& sg_map) {
  const SceneSelection s = select_for_bundle(in.scene, in.fabrics, in.sgs, o, sg_map);
  in.sgs = s.sgs;
  in.scene = refine_and_order_meshes(std::move(in.scene), s.subdivision);  // the mesh the visibility was baked on
  std::fputs(set_pass_meshes(in.scene, "  ").c_str(), stderr);
  add_scene_sections(writer, in);
  add_selection_sections(writer, s, o);
  char buf[300];
  std::snprintf(buf, sizeof buf, "selected for target %g: %s, error %.4f%s", s.target, s.description.c_str(),
                s.chosen.error, s.reached ? "" : " (unreachable: closest)");
  return buf;
}

std::string add_rung_choice(bundle::BundleWriter& writer, const SceneBundleInput& in, ShadingData baked,
                            const SelectionViewOptions& views, const std::filesystem::path& cache,
                            const std::function<void(const std::string&)>& log) {
  if (baked.masks.empty()) return "no occluded cloth: no rung to choose (the SDF and the masks agree on open cloth)";
  auto say = [&log](const std::string& line) { log ? log(line) : void(std::fprintf(stderr, "  choose rung: %s\n", line.c_str())); };
  const RungChoice c = choose_rung(in.scene, in.fabrics, in.sgs, std::make_shared<const ShadingData>(std::move(baked)),
                                   kVertexRungCandidates, views, cache.empty() ? default_reference_cache() : cache, say);
  writer.add_json(kSelectionSection, rung_choice_json(c));
  std::string line = "rung " + c.method + " (";
  char buf[64];
  for (const auto& m : c.measured) {
    std::snprintf(buf, sizeof buf, "%.2f %%", 100.0 * m.error);
    line += (line.back() == '(' ? "" : ", ") + m.method + " " + buf;
  }
  std::snprintf(buf, sizeof buf, " on %d views, %.1f s)", c.views, c.seconds);
  return line + buf;
}

}  // namespace weft
