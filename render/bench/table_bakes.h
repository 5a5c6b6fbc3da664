#pragma once
// iwasaki draws from seed 000 tables: baked in memory, once per scene, fabric set and setting
// (small grids with --quick; the paper's 48 otherwise, minutes each on two cores). Every iwasaki
// variant of the runtime (e.g. iwasaki_vertex) reads the same bundle, and mizutani takes its W
// tables from it (baked for the paper's tangent samples).
#include <map>
#include <memory>
#include <string>

#include "bake/scene_bake.h"
#include "bench/bench_options.h"

namespace weft::bench {

class TableBakes {
public:
  explicit TableBakes(const BenchOptions& o) : options_(o) {}

  // The paper's settings at the run's grid (and SDF 16 with --quick), no progress shown.
  IwasakiBakeOptions paper_options() const;
  // "scene/fabric/fabric...": what a bake depends on besides its options.
  static std::string key(const Scene& scene, const std::map<std::string, Fabric>& fabrics);
  // The bake stored under `key`, baked with `o` on first use (a line on stderr with its time).
  std::shared_ptr<const IwasakiBundleData> bake(const std::string& key, const Scene& scene,
                                                const std::map<std::string, Fabric>& fabrics,
                                                const IwasakiBakeOptions& o);
  // The paper-default bundle for a method that reads seed 000 tables; null for the others.
  std::shared_ptr<const IwasakiBundleData> tables_for(const std::string& method, const Scene& scene,
                                                      const std::map<std::string, Fabric>& fabrics);

private:
  const BenchOptions& options_;
  std::map<std::string, std::shared_ptr<const IwasakiBundleData>> bakes_;
};

}  // namespace weft::bench
