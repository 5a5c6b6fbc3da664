#pragma once
// Registry entries of the sheer methods (sheer.h): `sheer` (per pixel) and `sheer_vertex` (per
// vertex, source and alpha interpolated), the thin layer over iwasaki with its visibility,
// drawn from a bundle's weighting tables by iwasaki's GPU side (iwasaki_cloth.h) with the sheer's
// shaders; see-through, measured against the thin-layer reference on the curtain scenes.
#include <string_view>
#include <vector>

#include "methods/runtime_method.h"

namespace weft::methods {
RuntimeMethod sheer_method();
RuntimeMethod sheer_vertex_method();
}  // namespace weft::methods
