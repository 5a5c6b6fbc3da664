#pragma once
// Method `sheen`'s registry entry and uniforms: the glTF sheen BRDF, SG-lit (sheen.glsl over
// shaders/sg_lighting.glsl; C++ twin sheen.h, fed by the same SheenParams).
#include "gl/gl_program.h"
#include "methods/runtime_method.h"
#include "methods/sheen/sheen.h"

namespace weft::gpu {
void upload_sheen(const GlProgram& program, const SheenParams& p);
}  // namespace weft::gpu

namespace weft::methods {
RuntimeMethod sheen_method();
}  // namespace weft::methods
