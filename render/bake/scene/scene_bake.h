#pragma once
// The weighting-table stage of `weft bake` (and of `weft render --method iwasaki` without a bundle):
// weighting tables for each cloth fabric, per-vertex visibility PCA for each occluded object
// (cloth, floor, occluders), and κ when any object is occluded. Progress goes to the caller's
// display per stage; a summary of each stage on stderr unless quiet.
#include <array>
#include <functional>
#include <map>
#include <string>

#include "runtime/shading_data.h"
#include "bake/visibility/scene_visibility.h"
#include "bundle/bundle_writer.h"
#include "core/fabric.h"
#include "scene/scene.h"

namespace weft {

// Opens the progress display of one stage ("T tables linen_plain") when the stage starts; the
// returned function is then called with the fraction of the stage done (1.0 at its end).
using StageProgress = std::function<std::function<void(double)>(const std::string& stage)>;

struct ShadingDataBakeOptions {
  double target_error = 0.0;  // > 0: bake_selection picks the table settings (and prints its table)
  int grid = 0;               // > 0: ξ, ω_o and ω_i grids n×n instead of the paper's 48×48 (tests, previews)
  std::array<int, 2> tangent_samples{0, 0};  // > 0: override the paper's (or the selection's) counts
  double svd_error = 0.0;     // > 0: override the SVD truncation target (the paper's 0.01, or the selection's)
  int lambda_levels = 0;      // > 0: sharpness levels over the settings' λ range instead of their own count
  // Either half alone (`weft bench` sweeps one knob and reuses the other half of its bundle).
  bool bake_tables = true;      // weighting tables for each cloth fabric
  bool bake_visibility = true;  // per-object visibility, and κ when any object is occluded
  SceneVisibilityOptions visibility;
  // > 0: occluded cloth objects also get a per-vertex visibility mask of this many cells per side
  // (runtime/visibility_mask.h; kMaskResolution: cells of ≈ 2.2°, 512 B per vertex), which only the
  // mask and quadrature methods read; 0: none, the bundle stays small.
  int mask_resolution = 0;
  bool quiet = false;         // no progress or summary
  StageProgress progress;     // none: no progress shown
};

struct ShadingDataBakeReport {
  double tables_s = 0, visibility_s = 0, kappa_s = 0;
};

// `fabrics`: preset → fabric for every cloth object's preset.
ShadingData bake_shading_data(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                               const ShadingDataBakeOptions& options, ShadingDataBakeReport* report = nullptr);

// `weft bake`'s weighting-table sections: bakes for the scene's cloth fabrics (parsed from the fabric
// texts the bundle stores, preset → JSON) and adds the sections to `writer`. Returns the
// summary line: "tables for N fabric(s) T s, visibility for M object(s) V s, kappa K s".
// `baked`: also gets the data written (for measuring what the bundle will draw).
std::string add_baked_sections(bundle::BundleWriter& writer, const Scene& scene,
                               const std::map<std::string, std::string>& fabric_texts, const ShadingDataBakeOptions& options,
                               ShadingData* baked = nullptr);

}  // namespace weft
