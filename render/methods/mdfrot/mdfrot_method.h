#pragma once
// Method `mdfrot`'s registry entry and uniforms: per-thread microfacet lobes rotated along the
// tangent curve, SG-lit (mdfrot.glsl over shaders/sg_lighting.glsl; C++ twin mdfrot.h, fed by
// the same MdfrotParams).
#include "gl/gl_program.h"
#include "methods/mdfrot/mdfrot.h"
#include "methods/runtime_method.h"

namespace weft::gpu {
// Throws GpuError past kMdfrotMaxSamples samples per thread.
void upload_mdfrot(const GlProgram& program, const MdfrotParams& p);
}  // namespace weft::gpu

namespace weft::methods {
RuntimeMethod mdfrot_method();
}  // namespace weft::methods
