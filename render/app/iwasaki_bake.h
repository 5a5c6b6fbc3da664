#pragma once
// The seed 000 stage of `weft bake` (and of `weft render --method iwasaki` without a bundle):
// weighting tables for each cloth fabric, per-vertex visibility PCA for each occluded cloth
// object, and κ when any object is occluded. Progress bars on stderr, a summary on request.
#include <map>
#include <string>

#include "bake/iwasaki_bundle.h"
#include "bake/scene_visibility.h"
#include "core/fabric.h"
#include "scene/scene.h"

namespace weft {

struct IwasakiBakeOptions {
  double target_error = 0.0;  // > 0: bake_selection picks the table settings (and prints its table)
  SceneVisibilityOptions visibility;
  bool quiet = false;         // no progress bars or summary
};

struct IwasakiBakeReport {
  double tables_s = 0, visibility_s = 0, kappa_s = 0;
};

// `fabrics`: preset → fabric for every cloth object's preset.
IwasakiBundleData bake_iwasaki(const Scene& scene, const std::map<std::string, Fabric>& fabrics,
                               const IwasakiBakeOptions& options, IwasakiBakeReport* report = nullptr);

}  // namespace weft
