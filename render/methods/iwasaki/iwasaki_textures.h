#pragma once
// The baked weighting-table data as GLES textures for methods/iwasaki/iwasaki.glsl: one fabric's weighting-table
// factors (two RGBA32F array textures, four SVD ranks per layer), one object's visibility per
// (vertex, SG) (RGBA32F, refilled when the lighting changes) and the sigmoid gain table κ (R32F 3D).
// Linear filtering of float textures needs GL_OES_texture_float_linear (llvmpipe and desktop
// drivers have it); constructors throw GpuError without it.
#include <GLES3/gl3.h>

#include <vector>

#include "runtime/sigmoid_gain_table.h"
#include "runtime/weighting_tables.h"
#include "gl/gl_program.h"
#include "gl/gl_texture.h"
#include "methods/iwasaki/broad_lobe_quadrature.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "scene/mesh.h"

namespace weft::gpu {

// Must match MAX_TABLES in iwasaki.glsl.
inline constexpr int kMaxIwasakiTables = 512;
inline constexpr int kMaxIwasakiLevels = 32;  // iwasaki.glsl's MAX_LEVELS

class WeightingTablesTexture {
public:
  explicit WeightingTablesTexture(const WeightingTables& tables);
  // Binds to units `unit`, `unit + 1` and sets the table uniforms of `program` (in use).
  void bind(const GlProgram& program, int unit) const;
  const WeightingTables& tables() const { return *tables_; }

private:
  const WeightingTables* tables_;
  GlTexture u_, v_;
  std::vector<GLint> index_;  // (first layer, layers) per table
};

// SgVisibility's (d, ∂d/∂θ', ∂d/∂φ') per (vertex, SG), refilled when the lighting changes:
// RGBA32F, texel ((v mod P)·sgs + k, v div P) for P vertices per row, read with texelFetch.
class SgVisibilityTexture {
public:
  void upload(const SgVisibility& visibility);
  void bind(const GlProgram& program, int unit) const;

private:
  GlTexture texture_;
  int per_row_ = 1;
};

// BroadLobeBits' words per vertex (broad_lobe_quadrature.h) as RGBA32UI, four words a texel,
// texel ((v mod P)·T + w/4, v div P) for P vertices per row and T texels per vertex, read with
// texelFetch by broad_lobe_quadrature.glsl.
class BroadLobeBitsTexture {
public:
  void upload(const BroadLobeBits& bits);
  void bind(const GlProgram& program, int unit) const;

private:
  GlTexture texture_;
  int per_row_ = 1;
};

class KappaTexture {
public:
  explicit KappaTexture(const SigmoidGainTable& table);
  void bind(const GlProgram& program, int unit) const;

private:
  GlTexture texture_;
  SigmoidGainTableSpec spec_;
};

// A mesh drawn de-indexed for per-pixel visibility: every corner of triangle t becomes its own
// vertex carrying the triangle's three source vertex indices (`corners`) and a one-hot
// barycentric (`bary`), attributes 4 and 5 of iwasaki.vert.
TriangleMesh deindexed(const TriangleMesh& mesh, std::vector<glm::vec3>& corners, std::vector<glm::vec3>& bary);

}  // namespace weft::gpu
