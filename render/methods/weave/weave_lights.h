#pragma once
// The lights the weave layer's factor takes (methods/weave/weave_ratio.h): the lighting's SGs with
// each broad lobe split into a few sharper ones, and each light's share that the object's own
// geometry leaves open at every vertex. The factor takes an SG as one point light; a thread's
// response to a broad lobe is its response spread over tens of degrees, not at one direction
// (an armchair cushion under an interior map: 10.9 % off the resolved reference with the lobes
// whole and no occlusion, 7.6 % with both below; docs/bench/weave/README.md).
#include <vector>

#include "core/spherical_gaussian.h"
#include "runtime/object_visibility.h"
#include "runtime/visibility_mask.h"
#include "scene/mesh.h"

namespace weft {

// An SG of sharpness below this is split; into this many lobes: one at its axis and the rest on a
// ring around it. Each part has sharpness 2λ and an equal share of the power, the ring at
// β = 1/√((1 − w₀)λ) (w₀ the centre's share), so that the parts' spread about the axis adds to
// the SG's own variance 1/λ per direction. Only the sky-wide lobes: each split adds four lights to
// the factor's work (splitting below λ = 10 put the studio map's linen close-up at 1.81× the
// rung's frame, for no change of its error; the interior map's cushion needs only its λ = 1 lobe split).
inline constexpr double kWeaveSplitSharpness = 4.0;
inline constexpr int kWeaveSplitParts = 5;

// `sgs` with the broad lobes split (broadest first, as many as keep the result within
// `max_lights`); every SG kept whole otherwise. Each part's power (sg_power) is 1/kWeaveSplitParts
// of its SG's.
SgLighting weave_lights(const SgLighting& sgs, int max_lights);

// Per vertex v and light k, at [v · lights.size() + k]: the share of light k's part above v's
// surface that no geometry blocks. From the object's visibility mask where it has one (the mask's
// G-weighted open share); else from its SDF, the light's Gaussian cut at the SDF's boundary,
// Φ(√λ·d) over the same cut at the horizon alone, Φ(√λ·e) (e the axis's elevation), so that the
// horizon, which the factor's horizon_light takes already, does not count twice; empty where the
// object has neither (unoccluded: every share 1). Throws std::invalid_argument where the mask or
// SDF is of another mesh.
std::vector<float> weave_light_visibility(const VisibilityMask* mask, const ObjectVisibility* sdf, const TriangleMesh& mesh,
                                          const SgLighting& lights);

// One object's lighting for the layer, computed on the CPU when the lighting changes.
struct WeaveLighting {
  SgLighting lights;              // weave_lights(sgs, max_lights)
  std::vector<float> visibility;  // weave_light_visibility (empty: unoccluded)
};
WeaveLighting weave_lighting(const SgLighting& sgs, int max_lights, const VisibilityMask* mask, const ObjectVisibility* sdf,
                             const TriangleMesh& mesh);

}  // namespace weft
