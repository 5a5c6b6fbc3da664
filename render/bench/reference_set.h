#pragma once
// The bench's reference renders: SG-lit (opaque cloth, or thin cloth for see-through methods)
// per case, and map-lit for the SG-count sweep, each read from the cache when every input is
// the same (reference_cache.h) and rendered and stored otherwise, with a line on stderr.
// Each converges in the tangent samples N_j (reference/tangent_convergence.h): from
// --tangent-samples, doubled up to kReferenceTangentCap until the cloth of the check subset
// changes by at most --reference-tolerance (0: N_j fixed at --tangent-samples). The choice is
// cached under the render's inputs and the convergence settings; the render under its inputs
// and the N_j chosen, so no render is reused for another N_j.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_case.h"
#include "bench/bench_options.h"
#include "measure/reference_cache.h"
#include "lighting/env_map.h"
#include "reference/tangent_convergence.h"

namespace weft::bench {

// One reference of the run: the N_j it took and how it was chosen.
struct ReferenceRecord {
  std::string name;
  TangentConvergence tangent;  // steps empty: fixed N_j (tolerance 0)
  bool tangent_cached = false, image_cached = false;
  double render_seconds = 0.0;  // the full render (0 when cached)
};

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
  const std::vector<ReferenceRecord>& records() const { return records_; }
  int cached() const { return cached_; }
  double render_seconds() const { return seconds_; }

private:
  // The render named `name`: its N_j (chosen or fixed), then the image, each from the cache or
  // computed and stored. `inputs` hashes everything but N_j.
  CachedReference render(const std::string& name, const std::string& label, const InputHash& inputs,
                         const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                         const ReferenceLighting& lighting, ReferenceRenderOptions options);

  const BenchOptions& options_;
  std::filesystem::path cache_;
  std::map<std::string, CachedReference> loaded_;
  std::vector<ReferenceRecord> records_;
  int rendered_ = 0, cached_ = 0;
  double seconds_ = 0.0;
};

}  // namespace weft::bench
