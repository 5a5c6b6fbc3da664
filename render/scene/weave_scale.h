#pragma once
// How big the weave is on a cloth object: tile coordinates (core/weave_layout.h) per UV unit.
// Scene units are metres; the fabric gives its repeat in centimetres (weave_repeat_cm).
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/fabric.h"
#include "scene/scene.h"

namespace weft {

// The mesh's length per UV unit along u and along v: each triangle's |∂P/∂u| and |∂P/∂v|,
// averaged with the triangle's UV area as weight. (1, 1) for a mesh without usable UVs.
glm::dvec2 uv_length(const TriangleMesh& mesh);

// Repeats per UV unit: the object's own weave_repeats_per_uv where it gives one, else the mesh's
// UV length against the fabric's repeat.
glm::dvec2 weave_tiles_per_uv(const SceneObject& object, const Fabric& fabric);

// Each vertex's weave coordinates (tile coordinates, core/weave_layout.h): its UV times the
// repeats per UV unit of its UV island (the triangles joined through shared vertices: an atlas's
// panels, cut apart at their seams). Each island takes its own UV length against the fabric's
// repeat, so panels laid out at different texel densities show threads of one size; the object's
// weave_repeats_per_uv, where it gives one, holds for every island, and an island without UV area
// takes the object's mean. Empty for a mesh without UVs.
std::vector<glm::dvec2> weave_coordinates(const SceneObject& object, const Fabric& fabric);

// Whether a triangle's weave coordinates collapse to a point or a line (its area at most 10⁻⁴ of
// its longest edge squared, or every edge under 10⁻⁹ of a repeat): no place for the threads, so
// the resolved weave keeps the fabric level there, as the weave layer does.
bool weave_degenerate_uvs(glm::dvec2 st0, glm::dvec2 st1, glm::dvec2 st2);

// The repeat's size on the object in metres (along u, along v): the fabric's own repeat, or the
// mesh's UV length over the object's weave_repeats_per_uv where it gives them.
glm::dvec2 weave_repeat_metres(const SceneObject& object, const Fabric& fabric);

// The scene's close-up camera, or, where it names none, its camera moved along the view toward the
// target until the smallest weave repeat of its cloth spans `repeat_pixels` on an image
// `height` pixels high (never farther than the camera already is).
Camera closeup_camera(const Scene& scene, const std::map<std::string, Fabric>& fabrics, int height,
                      double repeat_pixels = 24.0);

}  // namespace weft
