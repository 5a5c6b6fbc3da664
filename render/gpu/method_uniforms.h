#pragma once
// Uniform uploads of the SG-lit runtime methods (shaders/sg_lighting.glsl, sheen.glsl,
// mdfrot.glsl, thin.glsl), from the same parameter structs the C++ side evaluates
// (render/methods), so a parity test and the renderer feed the shaders identically.
#include <span>

#include "core/spherical_gaussian.h"
#include "gpu/gl_program.h"
#include "methods/mdfrot.h"
#include "methods/sheen.h"
#include "methods/thin.h"

namespace weft::gpu {

inline constexpr int kMaxSgs = 40;  // MAX_SGS in the shaders

// Throws GpuError past kMaxSgs.
void upload_sg_lighting(const GlProgram& program, std::span<const SphericalGaussian> sgs);
void upload_sheen(const GlProgram& program, const SheenParams& p);
// Throws GpuError past kMdfrotMaxSamples samples per thread.
void upload_mdfrot(const GlProgram& program, const MdfrotParams& p);
void upload_thin(const GlProgram& program, const ThinParams& p);

}  // namespace weft::gpu
