#pragma once
// Uploads a fabric and its tangent samples to the uniforms of shaders/microcylinder.glsl.
// Knob edits (albedo, gloss) go through here too: no re-bake, just new uniforms.
#include "core/cloth_bsdf.h"
#include "gl/gl_program.h"

namespace weft::gpu {

// Must match MAX_TANGENT_SAMPLES in the shader preamble (shader_preamble()).
inline constexpr int kMaxTangentSamples = 64;

// "#version 300 es", precision and the defines every Weft shader starts with. With the
// environment's WEFT_STRICT_GLSL set (tests, a driver's wrong pixels), the cases GLSL leaves
// undefined and drivers answer differently return NaN instead: pow(x, y) with x < 0 or x = 0 ≤ y,
// log and log2 of x ≤ 0, sqrt of x < 0 (llvmpipe answers pow(0, 0) with 1, NVIDIA with NaN).
std::string shader_preamble();

// Throws GpuError if a thread has more than kMaxTangentSamples samples.
void upload_fabric(const GlProgram& program, const ClothBsdf& bsdf);

}  // namespace weft::gpu
