#include "methods/fabric_uniforms.h"

#include <cstdlib>
#include <string>
#include <vector>

#include "gl/gl_error.h"

namespace weft::gpu {

namespace {
// Each trap defined before its macro, so it calls the built-in.
const char* kStrictGlsl = R"(float strict_nan() { return uintBitsToFloat(0x7fc00000u); }
float strict_pow(float x, float y) { return x < 0.0 || (x == 0.0 && y <= 0.0) ? strict_nan() : pow(x, y); }
float strict_log(float x) { return x <= 0.0 ? strict_nan() : log(x); }
float strict_log2(float x) { return x <= 0.0 ? strict_nan() : log2(x); }
float strict_sqrt(float x) { return x < 0.0 ? strict_nan() : sqrt(x); }
#define pow strict_pow
#define log strict_log
#define log2 strict_log2
#define sqrt strict_sqrt
)";
}  // namespace

std::string shader_preamble() {
  const char* strict = std::getenv("WEFT_STRICT_GLSL");
  return "#version 300 es\nprecision highp float;\nprecision highp int;\n#define MAX_TANGENT_SAMPLES " +
         std::to_string(kMaxTangentSamples) + "\n" + (strict && *strict && std::string(strict) != "0" ? kStrictGlsl : "");
}

void upload_fabric(const GlProgram& program, const ClothBsdf& bsdf) {
  program.use();
  std::vector<float> tilts(2 * kMaxTangentSamples, 0.0f), spreads(2 * kMaxTangentSamples, 0.0f),
      multiplicity(2 * kMaxTangentSamples, 0.0f);
  for (int j = 0; j < 2; ++j) {
    const ThreadParams& p = bsdf.fabric().threads[j];
    const int n = bsdf.sample_count(j);
    if (n > kMaxTangentSamples)
      throw GpuError("thread " + std::to_string(j + 1) + " has " + std::to_string(n) + " tangent samples; the GPU takes " +
                     std::to_string(kMaxTangentSamples));
    const std::string t = "u_threads[" + std::to_string(j) + "].";
    glUniform1f(program.uniform((t + "eta").c_str()), float(p.eta));
    glUniform3f(program.uniform((t + "albedo").c_str()), float(p.albedo.r), float(p.albedo.g), float(p.albedo.b));
    glUniform1f(program.uniform((t + "kd").c_str()), float(p.kd));
    glUniform1f(program.uniform((t + "gamma_s").c_str()), float(p.gamma_s));
    glUniform1f(program.uniform((t + "gamma_v").c_str()), float(p.gamma_v));
    glUniform1f(program.uniform((t + "coverage").c_str()), float(p.coverage));
    glUniform1i(program.uniform((t + "samples").c_str()), n);
    for (int k = 0; k < n; ++k) {
      tilts[j * kMaxTangentSamples + k] = float(bsdf.tilt(j, k));
      spreads[j * kMaxTangentSamples + k] = float(bsdf.tilt_spread(j, k));
      multiplicity[j * kMaxTangentSamples + k] = float(bsdf.sample_multiplicity(j, k));
    }
  }
  // Four to a vec4 (microcylinder.glsl says why).
  glUniform4fv(program.uniform("u_tilts"), 2 * kMaxTangentSamples / 4, tilts.data());
  // Only shaders that widen their lobes by it declare it (iwasaki.glsl); elsewhere a no-op.
  glUniform4fv(program.uniform("u_tilt_spreads"), 2 * kMaxTangentSamples / 4, spreads.data());
  glUniform4fv(program.uniform("u_sample_multiplicity"), 2 * kMaxTangentSamples / 4, multiplicity.data());
}

}  // namespace weft::gpu
