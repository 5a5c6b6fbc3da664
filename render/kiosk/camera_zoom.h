#pragma once
// The kiosk's zoom: the camera dollied from the scene's view toward its close-up
// (scene/weave_scale.h closeup_camera), and eased in time so a knob step glides.
#include <vector>

#include "core/fabric.h"
#include "scene/scene.h"

namespace weft {

// The camera t of the way (0 … 1) from `from` to `to`: target, up and field of view linear, the
// distance to the target geometric (each zoom step scales it by the same factor), the direction
// from the target normalised-linear.
Camera dolly(const Camera& from, const Camera& to, double t);

// The scene's close-up for the zoom knob: its closeup_camera, or one where a weave repeat of the
// cloth (`cloth`: the fabric of each cloth object, in order) spans 24 pixels of `height`.
Camera closeup_of(const Scene& scene, const std::vector<Fabric>& cloth, int height);

// The shown zoom `dt` seconds later, following `target` with time constant `tau`; snaps within 1e−3.
double ease_zoom(double shown, double target, double dt, double tau = 0.25);

}  // namespace weft
