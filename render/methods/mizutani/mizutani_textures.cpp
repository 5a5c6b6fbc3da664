#include "methods/mizutani/mizutani_textures.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/gl_error.h"
#include "methods/fabric_uniforms.h"

namespace weft::gpu {

namespace {
constexpr int kMaxTables = 256;  // MAX_W_TABLES in mizutani.glsl
constexpr int kMaxLevels = 16;   // MAX_W_LEVELS

GLuint nearest_texture(GLenum target) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(target, t);
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}
}  // namespace

MizutaniTextures::MizutaniTextures(const WeightingTables& w, const AzimuthalTable& az) {
  if (w.level_count() < 1 || w.level_count() > kMaxLevels)
    throw GpuError("mizutani: " + std::to_string(w.level_count()) + " sharpness levels; the shader takes 1.." +
                   std::to_string(kMaxLevels));
  if (int(w.tables.size()) > kMaxTables)
    throw GpuError("mizutani: " + std::to_string(w.tables.size()) + " weighting tables; the shader takes " +
                   std::to_string(kMaxTables));
  if (w.sample_count() > 2 * kMaxTangentSamples) throw GpuError("mizutani: too many tangent samples");
  if (az.settings.max_power < 10) throw GpuError("mizutani: the azimuthal table must hold powers 0..10");
  xi_n_ = w.xi_grid.n;
  wo_n_ = w.wo_grid.n;
  levels_ = w.level_count();
  for (double l : w.lambdas) log_lambdas_.push_back(float(std::log(l)));
  sample_table_.assign(w.sample_table.begin(), w.sample_table.end());

  // Every table's rank rows stacked: U rows over ξ nodes, V rows over ω_o nodes.
  int rows = 0;
  for (const CompressedTable& c : w.tables) {
    table_rows_.insert(table_rows_.end(), {rows, c.rank});
    rows += c.rank;
  }
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (std::max({rows, w.xi_grid.size(), w.wo_grid.size()}) > max_size)
    throw GpuError("mizutani: weighting tables need " + std::to_string(rows) + " rows of " +
                   std::to_string(std::max(w.xi_grid.size(), w.wo_grid.size())) + " texels; the GPU takes " +
                   std::to_string(max_size));
  std::vector<float> u(size_t(std::max(rows, 1)) * w.xi_grid.size(), 0.0f), v(size_t(std::max(rows, 1)) * w.wo_grid.size(), 0.0f);
  for (size_t d = 0; d < w.tables.size(); ++d) {
    const CompressedTable& c = w.tables[d];
    const int first = table_rows_[2 * d];
    for (int r = 0; r < c.rank; ++r) {
      for (int a = 0; a < w.xi_grid.size(); ++a) u[size_t(first + r) * w.xi_grid.size() + a] = c.u[size_t(a) * c.rank + r];
      for (int b = 0; b < w.wo_grid.size(); ++b) v[size_t(first + r) * w.wo_grid.size() + b] = c.v[size_t(b) * c.rank + r];
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  u_tex_ = nearest_texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, w.xi_grid.size(), std::max(rows, 1), 0, GL_RED, GL_FLOAT, u.data());
  v_tex_ = nearest_texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, w.wo_grid.size(), std::max(rows, 1), 0, GL_RED, GL_FLOAT, v.data());

  // Azimuthal: texel (φ_o, φ_k, group·L + λ') = powers 4·group .. 4·group + 3.
  const auto& s = az.settings;
  az_nodes_[0] = s.phi_o_nodes, az_nodes_[1] = s.phi_k_nodes, az_nodes_[2] = s.lambda_nodes;
  az_lambda_max_ = float(s.lambda_max);
  std::vector<float> texels(size_t(s.phi_o_nodes) * s.phi_k_nodes * s.lambda_nodes * 3 * 4, 0.0f);
  for (int m = 0; m <= 10; ++m)
    for (int l = 0; l < s.lambda_nodes; ++l)
      for (int k = 0; k < s.phi_k_nodes; ++k)
        for (int o = 0; o < s.phi_o_nodes; ++o) {
          const size_t z = size_t(m / 4) * s.lambda_nodes + l;
          texels[((z * s.phi_k_nodes + k) * s.phi_o_nodes + o) * 4 + m % 4] = float(az.node_ratio(m, l, k, o));
        }
  az_tex_ = nearest_texture(GL_TEXTURE_3D);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, s.phi_o_nodes, s.phi_k_nodes, 3 * s.lambda_nodes, 0, GL_RGBA, GL_FLOAT,
               texels.data());
  check_gl("mizutani: uploading the tables");
}

MizutaniTextures::~MizutaniTextures() {
  const GLuint t[] = {u_tex_, v_tex_, az_tex_};
  glDeleteTextures(3, t);
}

void MizutaniTextures::bind(const GlProgram& program, int first_unit) const {
  program.use();
  const GLuint tex[] = {u_tex_, v_tex_, az_tex_};
  const GLenum target[] = {GL_TEXTURE_2D, GL_TEXTURE_2D, GL_TEXTURE_3D};
  const char* name[] = {"u_w_u", "u_w_v", "u_azimuthal"};
  for (int i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE0 + first_unit + i);
    glBindTexture(target[i], tex[i]);
    glUniform1i(program.uniform(name[i]), first_unit + i);
  }
  glUniform1i(program.uniform("u_w_xi_n"), xi_n_);
  glUniform1i(program.uniform("u_w_wo_n"), wo_n_);
  glUniform1i(program.uniform("u_w_levels"), levels_);
  glUniform1fv(program.uniform("u_w_log_lambda"), GLsizei(log_lambdas_.size()), log_lambdas_.data());
  glUniform1iv(program.uniform("u_w_sample_table"), GLsizei(sample_table_.size()), sample_table_.data());
  glUniform2iv(program.uniform("u_w_table"), GLsizei(table_rows_.size() / 2), table_rows_.data());
  glUniform3i(program.uniform("u_az_nodes"), az_nodes_[0], az_nodes_[1], az_nodes_[2]);
  glUniform1f(program.uniform("u_az_lambda_max"), az_lambda_max_);
}

void upload_mizutani_lights(const GlProgram& program, std::span<const SphericalGaussian> sgs) {
  if (sgs.size() > size_t(kMizutaniMaxSgs))
    throw GpuError("mizutani: at most " + std::to_string(kMizutaniMaxSgs) + " SGs, got " + std::to_string(sgs.size()));
  program.use();
  std::vector<float> axes, lambdas, amplitudes;
  for (const SphericalGaussian& g : sgs) {
    axes.insert(axes.end(), {float(g.axis.x), float(g.axis.y), float(g.axis.z)});
    lambdas.push_back(float(g.sharpness));
    amplitudes.insert(amplitudes.end(), {float(g.amplitude.r), float(g.amplitude.g), float(g.amplitude.b)});
  }
  glUniform1i(program.uniform("u_sg_count"), int(sgs.size()));
  if (sgs.empty()) return;
  glUniform3fv(program.uniform("u_sg_axis"), GLsizei(sgs.size()), axes.data());
  glUniform1fv(program.uniform("u_sg_lambda"), GLsizei(sgs.size()), lambdas.data());
  glUniform3fv(program.uniform("u_sg_amplitude"), GLsizei(sgs.size()), amplitudes.data());
}

}  // namespace weft::gpu
