#pragma once
// iwasaki draws from weighting tables: baked in memory, once per scene, fabric set and setting
// (small grids with --quick; the paper's 48 otherwise, minutes each on two cores; the weighting
// tables, which depend on the fabrics only, once per fabric set). Every iwasaki variant of the
// runtime (e.g. iwasaki_vertex) reads the same bundle, and mizutani takes its W tables from it
// (baked for the paper's tangent samples). A scene with its cloth refined (--subdivide) reads
// the same tables with the cloth's visibility baked on the refined vertices.
#include <map>
#include <memory>
#include <string>

#include "bake/scene/scene_bake.h"
#include "bench/bench_options.h"

namespace weft::bench {

class TableBakes {
public:
  explicit TableBakes(const BenchOptions& o) : options_(o) {}

  // The paper's settings at the run's grid (and SDF 16 with --quick), no progress shown.
  ShadingDataBakeOptions paper_options() const;
  // "scene/fabric/fabric...": what a bake depends on besides its options.
  static std::string key(const Scene& scene, const std::map<std::string, Fabric>& fabrics);
  // The bake stored under `key`, baked with `o` on first use (a line on stderr with its time).
  std::shared_ptr<const ShadingData> bake(const std::string& key, const Scene& scene,
                                                const std::map<std::string, Fabric>& fabrics,
                                                const ShadingDataBakeOptions& o);
  // The paper-default bundle for a method that reads weighting tables; null for the others.
  std::shared_ptr<const ShadingData> tables_for(const std::string& method, const Scene& scene,
                                                      const std::map<std::string, Fabric>& fabrics);
  // tables_for(method, scene, fabrics) with the cloth objects' visibility replaced by theirs in
  // `refined` (scene/mesh_subdivision.h: `scene` with its cloth refined `levels`), baked once per
  // scene and level at the paper's visibility settings; `bake_s`: that bake's time.
  std::shared_ptr<const ShadingData> subdivided(const std::string& method, const Scene& scene,
                                                      const Scene& refined, int levels,
                                                      const std::map<std::string, Fabric>& fabrics, double& bake_s);

private:
  const BenchOptions& options_;
  std::map<std::string, std::shared_ptr<const ShadingData>> bakes_;
  std::map<std::string, std::shared_ptr<const ShadingData>> by_fabrics_;  // a bake holding each fabric set's tables
  struct Refined {
    std::map<size_t, ObjectVisibility> cloth;
    std::map<size_t, VisibilityMask> masks;  // baked on first use by a method that reads them
    double seconds = 0.0;
  };
  std::map<std::pair<std::string, int>, Refined> refined_;  // by scene and level
};

}  // namespace weft::bench
