#pragma once
// One benchmark case: a scene with its fabrics (preset → fabric) and environment map, and the
// SGs fitted to the map; for the thin-occluder scene also the sun's shadow at the accuracy size.
#include <map>
#include <memory>
#include <string>

#include "bench/bench_options.h"
#include "bench/shadow_mask.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "scene/scene.h"

namespace weft::bench {

// The thin-occluder stress case: the scene whose spout and handle shadow the cloth under a
// sharp sun. Its rows also get errors inside and beside the sun's shadow.
inline const std::string kThinOccluderScene = "teapot";

struct Case {
  std::string scene_name, fabric_label, env, tag;
  Scene scene;
  std::map<std::string, Fabric> fabrics;
  SgLighting sgs;
  std::shared_ptr<const ShadowMask> shadow;  // the thin-occluder scene, at the accuracy size
};

// `fabric` and `env`: a preset / map name, or "scene" for the scene's own. Throws InvalidOption
// for an unknown scene or a missing map.
Case make_case(const BenchOptions& o, const std::string& scene_name, const std::string& fabric, const std::string& env);

// What the thin-occluder table's text says of its case: the sun and the shadow's size.
std::string thin_occluder_text(const Case& c);

}  // namespace weft::bench
