#pragma once
// The SG lighting uniforms of shaders/sg_lighting.glsl (u_sg_count, u_sg_axis, u_sg_sharpness,
// u_sg_amplitude), shared by the SG-lit methods (sheen, mdfrot, thin) and the see-through
// methods' background.
#include <span>

#include "core/spherical_gaussian.h"
#include "gl/gl_program.h"

namespace weft::gpu {

inline constexpr int kMaxSgs = 40;  // MAX_SGS in the shaders

// Throws GpuError past kMaxSgs.
void upload_sg_lighting(const GlProgram& program, std::span<const SphericalGaussian> sgs);

}  // namespace weft::gpu
