#include "bench/table_bakes.h"

#include <algorithm>
#include <chrono>
#include <iostream>

#include "bake/visibility/visibility_mask_bake.h"
#include "bench/number_text.h"
#include "bench/stopwatch.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"
#include "runtime/visibility_mask.h"

namespace weft::bench {

ShadingDataBakeOptions TableBakes::paper_options() const {
  ShadingDataBakeOptions o;
  o.quiet = true;
  o.grid = options_.bake_grid;
  if (options_.quick) o.visibility.resolution = 16;
  // Masks only when a method reads them (an empty list runs every method).
  const auto& m = options_.methods;
  if (m.empty() || std::any_of(m.begin(), m.end(), [](const std::string& n) {
        const methods::RuntimeMethod* method = methods::find_method(n);
        return method && method->reads_visibility_masks();
      }))
    o.mask_resolution = kMaskResolution;
  return o;
}

std::string TableBakes::key(const Scene& scene, const std::map<std::string, Fabric>& fabrics) {
  std::string key = scene.name;
  for (const auto& [name, f] : fabrics) key += "/" + name;
  return key;
}

std::shared_ptr<const ShadingData> TableBakes::bake(const std::string& key, const Scene& scene,
                                                          const std::map<std::string, Fabric>& fabrics,
                                                          const ShadingDataBakeOptions& o) {
  auto& data = bakes_[key];
  if (!data) {
    std::cerr << "weft bench: baking weighting tables for " << key << " ..." << std::flush;
    const auto t = std::chrono::steady_clock::now();
    data = std::make_shared<ShadingData>(bake_shading_data(scene, fabrics, o));
    std::cerr << " " << fmt(seconds_since(t)) << " s\n";
  }
  return data;
}

std::shared_ptr<const ShadingData> TableBakes::tables_for(const std::string& method, const Scene& scene,
                                                                const std::map<std::string, Fabric>& fabrics) {
  if (!methods::method(method).reads_weighting_tables()) return nullptr;
  const std::string k = key(scene, fabrics);
  if (bakes_.count(k)) return bakes_.at(k);
  std::string fabric_set;
  for (const auto& [name, f] : fabrics) fabric_set += "/" + name;
  const auto same_tables = by_fabrics_.find(fabric_set);
  if (same_tables == by_fabrics_.end()) return by_fabrics_[fabric_set] = bake(k, scene, fabrics, paper_options());
  ShadingDataBakeOptions o = paper_options();
  o.bake_tables = false;  // another scene's bake holds this fabric set's tables
  auto data = std::make_shared<ShadingData>(*bake(k + " (visibility)", scene, fabrics, o));
  data->tables = same_tables->second->tables;
  return bakes_[k] = data;
}

std::shared_ptr<const ShadingData> TableBakes::subdivided(const std::string& method, const Scene& scene,
                                                                const Scene& refined, int levels,
                                                                const std::map<std::string, Fabric>& fabrics,
                                                                double& bake_s) {
  const auto base = tables_for(method, scene, fabrics);
  if (!base) return nullptr;
  auto [it, inserted] = refined_.try_emplace({scene.name, levels});
  if (inserted) {
    std::cerr << "weft bench: baking visibility of " << scene.name << "'s cloth subdivided " << levels << " ..."
              << std::flush;
    const auto t = std::chrono::steady_clock::now();
    for (size_t i = 0; i < refined.objects.size(); ++i)
      if (refined.objects[i].is_cloth())
        if (auto v = bake_object_visibility(refined, i, paper_options().visibility)) it->second.cloth.emplace(i, std::move(*v));
    it->second.seconds = seconds_since(t);
    std::cerr << " " << fmt(it->second.seconds) << " s\n";
  }
  // The base mesh's masks do not fit the refined vertices: bake them again for the methods that read them.
  const bool masks = methods::method(method).reads_visibility_masks();
  if (masks && it->second.masks.empty()) {
    std::cerr << "weft bench: baking visibility masks of " << scene.name << "'s cloth subdivided " << levels << " ..."
              << std::flush;
    const auto t = std::chrono::steady_clock::now();
    for (const auto& [i, v] : it->second.cloth)
      if (auto m = bake_visibility_mask(refined, i, kMaskResolution)) it->second.masks.emplace(i, std::move(*m));
    const double s = seconds_since(t);
    it->second.seconds += s;
    std::cerr << " " << fmt(s) << " s\n";
  }
  auto data = std::make_shared<ShadingData>(*base);
  for (size_t i = 0; i < refined.objects.size(); ++i)
    if (refined.objects[i].is_cloth()) data->visibility.erase(i), data->masks.erase(i);
  for (const auto& [i, v] : it->second.cloth) data->visibility.emplace(i, v);
  if (masks)
    for (const auto& [i, m] : it->second.masks) data->masks.emplace(i, m);
  bake_s = it->second.seconds;
  return data;
}

}  // namespace weft::bench
