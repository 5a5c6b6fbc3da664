#pragma once
// The bench's reference renders: SG-lit (opaque cloth, or thin cloth for see-through methods)
// per case, and map-lit for the SG-count sweep, each read from the cache when every input is
// the same (reference_cache.h) and rendered and stored otherwise, with a line on stderr.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "bench/bench_case.h"
#include "bench/bench_options.h"
#include "bench/reference_cache.h"
#include "lighting/env_map.h"

namespace weft::bench {

class ReferenceSet {
public:
  ReferenceSet(const BenchOptions& o, std::filesystem::path cache) : options_(o), cache_(std::move(cache)) {}

  // Under the case's SGs at the accuracy size; kept for the run once loaded.
  const CachedReference& sg_lit(const Case& c, bool thin);
  // Lit by the map itself as 128x64 stratified cells (the SG fit's error counts against it);
  // `scene_arg` is the scene as --scenes named it (a preset or a path).
  CachedReference map_lit(const std::string& scene_arg, const Scene& s, const std::map<std::string, Fabric>& fabrics,
                          const std::filesystem::path& env_file, std::shared_ptr<const EnvMap> map);

  int rendered() const { return rendered_; }
  int cached() const { return cached_; }
  double render_seconds() const { return seconds_; }

private:
  const BenchOptions& options_;
  std::filesystem::path cache_;
  std::map<std::string, CachedReference> loaded_;
  int rendered_ = 0, cached_ = 0;
  double seconds_ = 0.0;
};

}  // namespace weft::bench
