#pragma once
// Method `thin`'s registry entry and uniforms: the thin see-through layer over sgpoint's
// microcylinder shading (thin.glsl, thin_over_sgpoint.glsl; C++ twin thin.h, fed by the same
// ThinParams). The bench measures it against the thin-layer reference, on the curtain only.
#include "gl/gl_program.h"
#include "methods/runtime_method.h"
#include "methods/thin/thin.h"

namespace weft::gpu {
void upload_thin(const GlProgram& program, const ThinParams& p);
}  // namespace weft::gpu

namespace weft::methods {
RuntimeMethod thin_method();
}  // namespace weft::methods
