#include "methods/iwasaki/iwasaki_textures.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "gl/gl_error.h"
#include "methods/fabric_uniforms.h"

namespace weft::gpu {

namespace {
void require_float_linear() {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i)
    if (std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i)), "GL_OES_texture_float_linear") == 0)
      return;
  throw GpuError("the GL driver cannot filter float textures (no GL_OES_texture_float_linear): method iwasaki needs it");
}
void linear_clamped(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}
}  // namespace

WeightingTablesTexture::WeightingTablesTexture(const WeightingTables& t) : tables_(&t) {
  require_float_linear();
  if (t.level_count() > kMaxIwasakiLevels)
    throw GpuError("method iwasaki: " + std::to_string(t.level_count()) + " λ levels, at most " +
                   std::to_string(kMaxIwasakiLevels));
  if (int(t.tables.size()) > kMaxIwasakiTables)
    throw GpuError("method iwasaki: " + std::to_string(t.tables.size()) + " weighting tables; the shader takes " +
                   std::to_string(kMaxIwasakiTables));
  int layers = 0;
  for (const CompressedTable& c : t.tables) {
    index_.push_back(layers);
    index_.push_back((c.rank + 3) / 4);
    layers += (c.rank + 3) / 4;
  }
  GLint max_layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (layers > max_layers)
    throw GpuError("method iwasaki: the tables need " + std::to_string(layers) + " texture layers, the driver has " +
                   std::to_string(max_layers));
  auto upload = [&](const GlTexture& tex, int n, bool is_u) {
    const size_t nodes = size_t(n) * n;
    std::vector<float> texels(nodes * 4 * std::max(layers, 1), 0.0f);
    int layer = 0;
    for (const CompressedTable& c : t.tables) {
      const std::vector<float>& f = is_u ? c.u : c.v;
      for (size_t node = 0; node < nodes; ++node)
        for (int r = 0; r < c.rank; ++r) texels[((layer + r / 4) * nodes + node) * 4 + r % 4] = f[node * c.rank + r];
      layer += (c.rank + 3) / 4;
    }
    glBindTexture(GL_TEXTURE_2D_ARRAY, tex.id());
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, n, n, std::max(layers, 1), 0, GL_RGBA, GL_FLOAT, texels.data());
    linear_clamped(GL_TEXTURE_2D_ARRAY);
  };
  upload(u_, t.xi_grid.n, true);
  upload(v_, t.wo_grid.n, false);
  check_gl("uploading the weighting tables");
}

void WeightingTablesTexture::bind(const GlProgram& p, int unit) const {
  const WeightingTables& t = *tables_;
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, u_.id());
  glUniform1i(p.uniform("u_t_u"), unit);
  glActiveTexture(GL_TEXTURE0 + unit + 1);
  glBindTexture(GL_TEXTURE_2D_ARRAY, v_.id());
  glUniform1i(p.uniform("u_t_v"), unit + 1);
  // The shader's tables are packed four scalars to a vector (iwasaki.glsl says why): each upload
  // is padded to whole vectors.
  auto padded = [](auto values) {
    values.resize((values.size() + 3) / 4 * 4);
    return values;
  };
  const std::vector<GLint> tables = padded(index_);
  glUniform4iv(p.uniform("u_tables"), GLsizei(tables.size() / 4), tables.data());
  glUniform1i(p.uniform("u_levels"), t.level_count());
  std::vector<GLfloat> log_lambdas;
  for (double l : t.lambdas) log_lambdas.push_back(GLfloat(std::log(l)));
  log_lambdas = padded(std::move(log_lambdas));
  glUniform4fv(p.uniform("u_log_lambdas"), GLsizei(log_lambdas.size() / 4), log_lambdas.data());
  std::vector<GLint> sample_table(2 * kMaxTangentSamples, 0);
  for (int j = 0, s = 0; j < 2; ++j)
    for (int k = 0; k < t.tangent_samples[j]; ++k, ++s) sample_table[j * kMaxTangentSamples + k] = t.sample_table[s];
  glUniform4iv(p.uniform("u_sample_table"), GLsizei(sample_table.size() / 4), sample_table.data());
  glUniform1f(p.uniform("u_xi_n"), float(t.xi_grid.n));
  glUniform1f(p.uniform("u_wo_n"), float(t.wo_grid.n));
}

void SgVisibilityTexture::upload(const SgVisibility& vis) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  const int sgs = std::max(vis.sgs, 1);
  per_row_ = std::max(1, int((vis.vertices + max_size - 1) / max_size));
  const int width = per_row_ * sgs, height = std::max(1, int((vis.vertices + per_row_ - 1) / per_row_));
  if (width > max_size) throw GpuError("method iwasaki: " + std::to_string(vis.vertices) + " vertices × " + std::to_string(sgs) +
                                       " SGs do not fit a " + std::to_string(max_size) + "² texture");
  std::vector<float> texels(size_t(width) * height * 4, 0.0f);
  for (size_t v = 0; v < vis.vertices; ++v)
    for (int k = 0; k < vis.sgs; ++k) {
      const size_t x = (v % per_row_) * sgs + k, y = v / per_row_;
      const float* src = &vis.values[(v * vis.sgs + k) * 3];
      std::memcpy(&texels[(y * width + x) * 4], src, 3 * sizeof(float));
    }
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  check_gl("uploading the per-SG visibility");
}

void SgVisibilityTexture::bind(const GlProgram& p, int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glUniform1i(p.uniform("u_sg_visibility"), unit);
  glUniform1i(p.uniform("u_sg_visibility_per_row"), per_row_);
}

namespace {
constexpr int kBroadTexelsPerVertex = (kBroadLobeWordsPerVertex + 3) / 4;
}

void BroadLobeBitsTexture::upload(const BroadLobeBits& bits) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  per_row_ = std::max(1, std::min(256, int(max_size) / kBroadTexelsPerVertex));
  const int width = per_row_ * kBroadTexelsPerVertex, height = std::max(1, int((bits.vertices + per_row_ - 1) / per_row_));
  if (height > max_size)
    throw GpuError("broad lobe quadrature: " + std::to_string(bits.vertices) + " vertices do not fit a " +
                   std::to_string(max_size) + "² texture");
  std::vector<GLuint> texels(size_t(width) * height * 4, 0u);
  for (size_t v = 0; v < bits.vertices; ++v) {
    const size_t first = ((v / per_row_) * width + (v % per_row_) * kBroadTexelsPerVertex) * 4;
    std::memcpy(&texels[first], &bits.words[v * kBroadLobeWordsPerVertex], kBroadLobeWordsPerVertex * sizeof(GLuint));
  }
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32UI, width, height, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  check_gl("uploading the broad lobes' cell bits");
}

void BroadLobeBitsTexture::bind(const GlProgram& p, int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glUniform1i(p.uniform("u_broad_bits"), unit);
  glUniform1i(p.uniform("u_broad_bits_per_row"), per_row_);
  glUniform1i(p.uniform("u_broad_texels_per_vertex"), kBroadTexelsPerVertex);
  glUniform1i(p.uniform("u_broad_grid"), kBroadLobeGrid);
  glUniform1i(p.uniform("u_broad_words_per_sg"), kBroadLobeWordsPerSg);
}

KappaTexture::KappaTexture(const SigmoidGainTable& t) : spec_(t.spec()) {
  require_float_linear();
  // Stored [σ_l][σ'][β] with β fastest: x = β, y = σ', z = σ_l.
  glBindTexture(GL_TEXTURE_3D, texture_.id());
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R32F, spec_.beta_count, spec_.sigma_prime_count, spec_.sigma_l_count, 0, GL_RED,
               GL_FLOAT, t.normalized_gains().data());
  linear_clamped(GL_TEXTURE_3D);
  check_gl("uploading the kappa table");
}

void KappaTexture::bind(const GlProgram& p, int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_3D, texture_.id());
  glUniform1i(p.uniform("u_kappa"), unit);
  glUniform3f(p.uniform("u_kappa_n"), float(spec_.sigma_l_count), float(spec_.sigma_prime_count), float(spec_.beta_count));
  glUniform2f(p.uniform("u_kappa_sigma"), float(spec_.sigma_min), float(spec_.sigma_max));
}

TriangleMesh deindexed(const TriangleMesh& m, std::vector<glm::vec3>& corners, std::vector<glm::vec3>& bary) {
  TriangleMesh out;
  corners.clear();
  bary.clear();
  for (const auto& t : m.triangles) {
    const glm::vec3 ids{float(t[0]), float(t[1]), float(t[2])};  // exact below 2^24 vertices
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = t[k];
      out.positions.push_back(m.positions[i]);
      out.normals.push_back(i < m.normals.size() ? m.normals[i] : glm::dvec3(0, 0, 1));
      out.warps.push_back(i < m.warps.size() ? m.warps[i] : glm::dvec3(1, 0, 0));
      if (!m.uvs.empty()) out.uvs.push_back(m.uvs[i]);
      corners.push_back(ids);
      glm::vec3 b(0.0f);
      b[k] = 1.0f;
      bary.push_back(b);
    }
    const uint32_t first = uint32_t(out.positions.size() - 3);
    out.triangles.push_back({first, first + 1, first + 2});
  }
  return out;
}

}  // namespace weft::gpu
