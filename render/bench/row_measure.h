#pragma once
// One row of the ladder: a GPU method on a case at the speed size (median frame time) and the
// accuracy size (relative RMSE over the cloth pixels, over the Lambertian pixels, and for the
// thin-occluder scene inside and beside the sun's shadow), against the case's reference; the
// method's image, its error map and the reference (once) as PNGs under the output folder.
#include <filesystem>
#include <memory>
#include <set>
#include <string>

#include "runtime/shading_data.h"
#include "bench/bench_case.h"
#include "bench/bench_options.h"
#include "bench/bench_results.h"
#include "bench/ladder.h"
#include "bench/reference_set.h"

namespace weft::bench {

class RowMeasure {
public:
  RowMeasure(const BenchOptions& o, std::filesystem::path out, ReferenceSet& references)
      : options_(o), out_(std::move(out)), references_(references) {}

  // `label`: the row's method column; `file_id`: its images' names; `bundle`: weighting tables
  // for the methods that read them; `drawn`: the scene the frames draw when not the case's own
  // (its cloth refined, scene/mesh_subdivision.h), against the case's reference.
  Row measure(const Case& c, const LadderEntry& m, const std::string& label, const std::string& file_id,
              std::shared_ptr<const ShadingData> bundle, const Scene* drawn = nullptr);
  const std::string& renderer() const { return renderer_; }  // GL_RENDERER of the last frame

private:
  const BenchOptions& options_;
  std::filesystem::path out_;
  ReferenceSet& references_;
  std::set<std::string> written_;  // reference PNGs written this run
  std::string renderer_;
};

}  // namespace weft::bench
