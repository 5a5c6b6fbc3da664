#pragma once
// Method `mizutani`'s registry entry: the weighting tables (those of iwasaki) with an
// azimuthal table (mizutani.glsl, textures in mizutani_textures.h; C++ twin mizutani.h). It runs
// with the paper's tangent samples, which its tables are baked for: a bundle's weighting tables
// serve when baked for the same samples, else it bakes them (a minute on two cores).
#include "methods/runtime_method.h"

namespace weft::methods {
RuntimeMethod mizutani_method();
}  // namespace weft::methods
