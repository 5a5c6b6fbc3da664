#pragma once
// The tables of method `mizutani` as GL textures and the uniforms of methods/mizutani/mizutani.glsl:
// the weighting tables T_{t,λ} (U, V factors as R32F) and the azimuthal table T_m/Z (RGBA32F,
// powers packed four to a texel). Uploaded once per bake; knob edits do not touch them.
#include <span>
#include <vector>

#include "runtime/azimuthal_table.h"
#include "runtime/weighting_tables.h"
#include "core/spherical_gaussian.h"
#include "gl/gl_program.h"

namespace weft::gpu {

inline constexpr int kMizutaniMaxSgs = 40;  // MAX_SGS the mizutani program is built with

class MizutaniTextures {
public:
  // Needs a current GLES 3 context. Throws GpuError if the tables exceed the shader's limits.
  MizutaniTextures(const WeightingTables& weights, const AzimuthalTable& azimuthal);
  ~MizutaniTextures();
  MizutaniTextures(const MizutaniTextures&) = delete;
  MizutaniTextures& operator=(const MizutaniTextures&) = delete;

  // Binds the textures to units first_unit .. first_unit + 2 and sets the table uniforms.
  void bind(const GlProgram& program, int first_unit = 0) const;

private:
  GLuint u_tex_ = 0, v_tex_ = 0, az_tex_ = 0;
  int xi_n_ = 0, wo_n_ = 0, levels_ = 0;
  std::vector<float> log_lambdas_;
  std::vector<int> sample_table_, table_rows_;  // table_rows_: (first row, rank) pairs
  int az_nodes_[3] = {0, 0, 0};
  float az_lambda_max_ = 0.0f;
};

// u_sg_count, u_sg_axis, u_sg_lambda, u_sg_amplitude. Throws GpuError past kMizutaniMaxSgs.
void upload_mizutani_lights(const GlProgram& program, std::span<const SphericalGaussian> sgs);

}  // namespace weft::gpu
