#include "methods/sg_lighting_uniforms.h"

#include <string>
#include <vector>

#include "gl/gl_error.h"

namespace weft::gpu {

void upload_sg_lighting(const GlProgram& program, std::span<const SphericalGaussian> sgs) {
  if (sgs.size() > size_t(kMaxSgs))
    throw GpuError("at most " + std::to_string(kMaxSgs) + " SGs, got " + std::to_string(sgs.size()));
  program.use();
  std::vector<float> axes, sharpness, amplitudes;
  for (const auto& g : sgs) {
    axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
    sharpness.push_back(float(g.sharpness));
    amplitudes.insert(amplitudes.end(), {float(g.amplitude.r), float(g.amplitude.g), float(g.amplitude.b)});
  }
  glUniform1i(program.uniform("u_sg_count"), GLint(sgs.size()));
  if (sgs.empty()) return;
  glUniform3fv(program.uniform("u_sg_axis"), GLsizei(sgs.size()), axes.data());
  glUniform1fv(program.uniform("u_sg_sharpness"), GLsizei(sgs.size()), sharpness.data());
  glUniform3fv(program.uniform("u_sg_amplitude"), GLsizei(sgs.size()), amplitudes.data());
}
}  // namespace weft::gpu
