#pragma once
// What the GLSL/C++ parity tests share: each case is one pixel of a float target, and its inputs
// (directions, frames) reach the fragment shader as float textures, so the GLSL and the C++ side
// evaluate the very same floats. Needs a current GLES 3 context (gpu::EglContext::headless()).
#include <GLES3/gl3.h>

#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl_program.h"
#include "gl/offscreen_target.h"
#include "gpu/egl_context.h"

namespace weft::test {

// A parity tolerance set on llvmpipe, on the driver the test runs on: a hardware driver's sin,
// cos, exp and division are approximations (NVIDIA's), which the model's sharp lobes (λ up to
// 1000, σ ≈ 0.045 rad) turn into relative differences of a few 1e-3 where llvmpipe's
// IEEE-exact ones stay within 1e-3 (docs/gpu/measured/h200: worst 3.7e-3 on the iwasaki rungs).
inline double driver_tolerance(double llvmpipe_tolerance) {
  return gpu::software_renderer() ? llvmpipe_tolerance : 4.0 * llvmpipe_tolerance;
}

// Case i's direction as RGBA floats (w = 0) in a per-pixel input.
inline void store_direction(std::vector<float>& input, int i, glm::vec3 d) {
  input[4 * i] = d.x, input[4 * i + 1] = d.y, input[4 * i + 2] = d.z, input[4 * i + 3] = 0.0f;
}
inline glm::dvec3 load_direction(const std::vector<float>& input, int i) {
  return {input[4 * i], input[4 * i + 1], input[4 * i + 2]};
}

// A fragment main for cases of (ω_o, frame): reads them from the samplers u_wo, u_n and u_u at
// its pixel and writes `call`, a vec4 expression of wo, n and u (the method's entry point).
inline std::string frame_case_main(const std::string& call) {
  return R"(
uniform highp sampler2D u_wo, u_n, u_u;
out vec4 colour;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 wo = texelFetch(u_wo, p, 0).xyz, n = texelFetch(u_n, p, 0).xyz, u = texelFetch(u_u, p, 0).xyz;
  colour = )" + call + ";\n}\n";
}

// A per-pixel input: the sampler's name in the shader and w×h RGBA floats.
using CaseInput = std::pair<const char*, const std::vector<float>*>;

// Runs `program` (fragment stage reading its inputs with texelFetch at gl_FragCoord) once per
// pixel of a w×h float target and returns the target's RGBA floats, row by row from the bottom.
// Inputs take texture units 0, 1, ... in order; the caller's own textures go above them.
inline std::vector<float> shade_cases(const gpu::GlProgram& program, int w, int h, const std::vector<CaseInput>& inputs) {
  program.use();
  std::vector<GLuint> textures(inputs.size());
  glGenTextures(GLsizei(textures.size()), textures.data());
  for (size_t k = 0; k < inputs.size(); ++k) {
    glActiveTexture(GLenum(GL_TEXTURE0 + k));
    glBindTexture(GL_TEXTURE_2D, textures[k]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, inputs[k].second->data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glUniform1i(program.uniform(inputs[k].first), GLint(k));
  }
  gpu::OffscreenTarget target(w, h);
  target.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> rgba = target.read_rgba();
  glDeleteTextures(GLsizei(textures.size()), textures.data());
  return rgba;
}

}  // namespace weft::test
