#pragma once
// Method `sgpoint`'s registry entry: each SG as a point light through the microcylinder model
// (sgpoint.frag over shaders/microcylinder.glsl; C++ twin sgpoint.h).
#include "methods/runtime_method.h"

namespace weft::methods {
RuntimeMethod sgpoint_method();
}  // namespace weft::methods
