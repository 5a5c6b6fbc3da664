#include "capture/response_calibration.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "image/texture_image.h"

namespace weft {

double ResponseModel::sensor(std::uint8_t code) const { return std::pow(srgb_to_linear(code / 255.0), beta); }

glm::dvec3 ResponseModel::relative(const std::array<std::uint8_t, 3>& code, double r2) const {
  const double falloff = 1.0 - vignetting * r2;
  return glm::dvec3(sensor(code[0]), sensor(code[1]), sensor(code[2])) / (falloff * scale);
}

CameraResponse ResponseModel::curve() const {
  CameraResponse r;
  for (int z = 0; z < 256; ++z) r.inverse_table[z] = static_cast<float>(sensor(static_cast<std::uint8_t>(z)));
  return r;
}

ResponseFit fit_response(const std::vector<ResponseSample>& samples) {
  // Usable: few clipped codes, not near black (where the curve's shape is noise).
  std::vector<const ResponseSample*> used;
  for (const ResponseSample& s : samples) {
    if (s.count == 0 || s.reflectance <= 0) continue;
    bool ok = true;
    for (int c = 0; c < 3 && ok; ++c) {
      std::uint32_t clipped = 0, dark = 0;
      for (int z = 250; z < 256; ++z) clipped += s.histogram[c][z];
      for (int z = 0; z < 4; ++z) dark += s.histogram[c][z];
      ok = clipped * 20 < s.count && dark * 2 < s.count;
    }
    if (ok) used.push_back(&s);
  }
  if (used.size() < 4) throw std::runtime_error("too few usable grey samples on the card (" + std::to_string(used.size()) + ")");
  ResponseFit best;
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<glm::dvec3> means(used.size());
  for (int bi = 0; bi <= 100; ++bi) {
    ResponseModel m;
    m.beta = 0.6 + 0.01 * bi;
    std::array<double, 256> table;
    for (int z = 0; z < 256; ++z) table[z] = m.sensor(static_cast<std::uint8_t>(z));
    for (size_t i = 0; i < used.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int z = 0; z < 256; ++z) sum += used[i]->histogram[c][z] * table[z];
        means[i][c] = std::max(sum / used[i]->count, 1e-6);
      }
    for (int vi = 0; vi <= 40; ++vi) {
      const double v = 0.01 * vi;
      glm::dvec3 log_scale(0);
      for (size_t i = 0; i < used.size(); ++i)
        log_scale += glm::log(means[i] / ((1 - v * used[i]->r2) * used[i]->reflectance));
      log_scale /= static_cast<double>(used.size());
      double cost = 0;
      for (size_t i = 0; i < used.size(); ++i) {
        const glm::dvec3 r = glm::log(means[i] / ((1 - v * used[i]->r2) * used[i]->reflectance)) - log_scale;
        cost += glm::dot(r, r);
      }
      if (cost < best_cost) {
        best_cost = cost;
        best.model.beta = m.beta;
        best.model.vignetting = v;
        best.model.scale = glm::exp(log_scale);
      }
    }
  }
  best.samples_used = static_cast<int>(used.size());
  best.rms_log_error = std::sqrt(best_cost / (3.0 * used.size()));
  return best;
}

}  // namespace weft
