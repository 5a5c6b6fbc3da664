#pragma once
// The kiosk's turns about the world's +Z (up): the slow camera turntable, and the environment
// knob's rotation of the light.
#include "core/spherical_gaussian.h"
#include "scene/scene.h"

namespace weft {

// Every SG's axis turned by `deg` degrees about +Z.
SgLighting rotated_about_z(const SgLighting& sgs, double deg);
// What the turntable turns about: the centre of the cloth objects' bounds (the product), of every
// object's where the scene has no cloth; the origin for an empty scene.
glm::dvec3 turntable_pivot(const Scene& scene);
// The camera's position and target turned by `deg` degrees about the vertical through `pivot`:
// the camera circles the product and keeps looking at it as it did (a glTF camera's target is
// only a point ahead of it, not the product).
Camera turned_about_z(const Camera& camera, double deg, const glm::dvec3& pivot);
// Frames over which to spread the recomputation of a per-vertex value (a share each frame) so that
// the turntable turns at most `refresh_deg` degrees between two recomputations of any vertex, at
// `turn_deg` degrees a frame; 1 (every frame) for refresh_deg = 0, at most kMaxRefreshShares.
inline constexpr int kMaxRefreshShares = 64;
int refresh_shares(double refresh_deg, double turn_deg);

}  // namespace weft
