#pragma once
// The kiosk's turns about the world's +Z (up): the slow camera turntable, and the environment
// knob's rotation of the light.
#include "core/spherical_gaussian.h"
#include "scene/scene.h"

namespace weft {

// Every SG's axis turned by `deg` degrees about +Z.
SgLighting rotated_about_z(const SgLighting& sgs, double deg);
// The camera's position turned by `deg` degrees about the vertical through its target.
Camera turned_about_z(const Camera& camera, double deg);

}  // namespace weft
