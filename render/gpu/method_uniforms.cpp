#include "gpu/method_uniforms.h"

#include <string>
#include <vector>

#include "gpu/egl_context.h"

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

void upload_sheen(const GlProgram& program, const SheenParams& p) {
  program.use();
  glUniform3f(program.uniform("u_sheen_diffuse"), float(p.diffuse.r), float(p.diffuse.g), float(p.diffuse.b));
  glUniform3f(program.uniform("u_sheen_colour"), float(p.sheen_colour.r), float(p.sheen_colour.g),
              float(p.sheen_colour.b));
  glUniform1f(program.uniform("u_sheen_roughness"), float(p.roughness));
}

void upload_mdfrot(const GlProgram& program, const MdfrotParams& p) {
  program.use();
  std::vector<float> tilts(2 * kMdfrotMaxSamples, 0.0f);
  for (int j = 0; j < 2; ++j) {
    const MdfrotThread& t = p.threads[j];
    const int n = int(t.tilts.size());
    if (n < 1 || n > kMdfrotMaxSamples)
      throw GpuError("mdfrot: thread " + std::to_string(j + 1) + " has " + std::to_string(n) +
                     " samples; the shader takes 1.." + std::to_string(kMdfrotMaxSamples));
    const std::string s = "u_mdf_threads[" + std::to_string(j) + "].";
    glUniform3f(program.uniform((s + "diffuse").c_str()), float(t.diffuse.r), float(t.diffuse.g), float(t.diffuse.b));
    glUniform1f(program.uniform((s + "f0").c_str()), float(t.f0));
    glUniform1f(program.uniform((s + "n_along").c_str()), float(t.n_along));
    glUniform1f(program.uniform((s + "n_across").c_str()), float(t.n_across));
    glUniform1f(program.uniform((s + "weight").c_str()), float(t.weight));
    glUniform1i(program.uniform((s + "samples").c_str()), n);
    for (int k = 0; k < n; ++k) tilts[j * kMdfrotMaxSamples + k] = float(t.tilts[k]);
  }
  glUniform1fv(program.uniform("u_mdf_tilts"), 2 * kMdfrotMaxSamples, tilts.data());
  glUniform1f(program.uniform("u_mdf_bulge"), float(p.bulge));
}

void upload_thin(const GlProgram& program, const ThinParams& p) {
  program.use();
  glUniform1f(program.uniform("u_thin_tau"), float(p.tau));
  glUniform3f(program.uniform("u_thin_albedo"), float(p.albedo.r), float(p.albedo.g), float(p.albedo.b));
}

}  // namespace weft::gpu
