#include "bake/selection/rung_choice.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "bake/writers/bundle_fabrics.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"

namespace weft {

RungChoice choose_rung(const Scene& scene, const std::map<std::string, std::string>& fabric_texts, const SgLighting& sgs,
                       std::shared_ptr<const ShadingData> data, const std::vector<std::string>& candidates,
                       const SelectionViewOptions& views, const std::filesystem::path& cache,
                       const std::function<void(const std::string&)>& log) {
  if (candidates.empty()) throw std::invalid_argument("choose_rung: no candidate method");
  const std::map<std::string, Fabric> fabrics = cloth_fabrics(scene, fabric_texts);
  std::vector<Fabric> cloth;  // per cloth object, as the renderer takes them
  for (const auto& o : scene.cloth_objects()) cloth.push_back(object_base_fabric(o, fabrics));
  if (cloth.empty()) throw std::invalid_argument("choose_rung: the scene has no cloth");
  const auto t0 = std::chrono::steady_clock::now();
  RungChoice out;
  const ViewReferences refs = view_references(scene, fabrics, fabric_texts, sgs, views, cache, log);
  out.views = int(refs.cameras.size());
  out.references_rendered = refs.rendered, out.references_cached = refs.cached;
  out.width = views.width, out.height = views.height;
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::OffscreenTarget target(views.width, views.height);
  for (const auto& name : candidates) {
    gpu::SceneRenderer renderer(scene, cloth, methods::method(name), 16, data);
    renderer.set_lighting(sgs);
    target.bind();
    RungMeasure m;
    m.method = name;
    m.view_errors = view_errors(renderer, refs, views.width, views.height);
    m.error = *std::max_element(m.view_errors.begin(), m.view_errors.end());
    if (log) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s: error %.4f (worst of %d views)", name.c_str(), m.error, out.views);
      log(buf);
    }
    out.measured.push_back(std::move(m));
  }
  size_t best = 0;
  for (size_t i = 1; i < out.measured.size(); ++i)
    if (out.measured[i].error < out.measured[best].error) best = i;  // a tie keeps the earlier (the SDF's)
  out.method = out.measured[best].method;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

std::string rung_choice_json(const RungChoice& c) {
  nlohmann::json j;
  j["method"] = c.method;
  j["chosen_by"] = "views";
  j["width"] = c.width, j["height"] = c.height, j["views"] = c.views;
  j["seconds"] = c.seconds;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& m : c.measured) list.push_back({{"method", m.method}, {"error", m.error}, {"view_errors", m.view_errors}});
  j["candidates"] = list;
  return j.dump(2);
}

}  // namespace weft
