#include "bench/table_bakes.h"

#include <chrono>
#include <iostream>

#include "bench/number_text.h"
#include "bench/stopwatch.h"
#include "gpu/scene_renderer.h"

namespace weft::bench {

IwasakiBakeOptions TableBakes::paper_options() const {
  IwasakiBakeOptions o;
  o.quiet = true;
  o.grid = options_.bake_grid;
  if (options_.quick) o.visibility.resolution = 16;
  return o;
}

std::string TableBakes::key(const Scene& scene, const std::map<std::string, Fabric>& fabrics) {
  std::string key = scene.name;
  for (const auto& [name, f] : fabrics) key += "/" + name;
  return key;
}

std::shared_ptr<const IwasakiBundleData> TableBakes::bake(const std::string& key, const Scene& scene,
                                                          const std::map<std::string, Fabric>& fabrics,
                                                          const IwasakiBakeOptions& o) {
  auto& data = bakes_[key];
  if (!data) {
    std::cerr << "weft bench: baking seed 000 tables for " << key << " ..." << std::flush;
    const auto t = std::chrono::steady_clock::now();
    data = std::make_shared<IwasakiBundleData>(bake_iwasaki(scene, fabrics, o));
    std::cerr << " " << fmt(seconds_since(t)) << " s\n";
  }
  return data;
}

std::shared_ptr<const IwasakiBundleData> TableBakes::tables_for(const std::string& method, const Scene& scene,
                                                                const std::map<std::string, Fabric>& fabrics) {
  if (!gpu::reads_seed000_tables(method)) return nullptr;
  return bake(key(scene, fabrics), scene, fabrics, paper_options());
}

}  // namespace weft::bench
