#include "core/tangent_curve.h"

#include <cmath>
#include <stdexcept>

#include <glm/glm.hpp>

namespace weft {

TangentCurve::TangentCurve(std::vector<double> offsets_deg, std::vector<double> lengths)
    : offsets_(std::move(offsets_deg)), lengths_(std::move(lengths)) {
  if (offsets_.empty()) throw std::invalid_argument("tangent curve needs at least one offset");
  for (double o : offsets_)
    if (!std::isfinite(o)) throw std::invalid_argument("tangent offset is not finite");
  if (offsets_.size() == 1) {
    if (!lengths_.empty()) throw std::invalid_argument("a single offset takes no segment lengths");
    total_ = 1.0;  // a straight thread: one sample direction, unit length
    return;
  }
  if (lengths_.size() != offsets_.size() - 1)
    throw std::invalid_argument("segment lengths must number offsets-1 (" +
                                std::to_string(offsets_.size() - 1) + "), got " +
                                std::to_string(lengths_.size()));
  for (double l : lengths_) {
    if (!std::isfinite(l) || l < 0.0)
      throw std::invalid_argument("segment length must be finite and >= 0, got " + std::to_string(l));
    total_ += l;
  }
  if (!(total_ > 0.0)) throw std::invalid_argument("tangent curve has zero total length");
}

double TangentCurve::tilt_at(double s) const {
  if (offsets_.size() == 1) return glm::radians(offsets_[0]);
  s = glm::clamp(s, 0.0, total_);
  double start = 0.0;
  size_t last = 0;
  for (size_t i = 0; i < lengths_.size(); ++i) {
    const double len = lengths_[i];
    if (len <= 0.0) continue;  // a jump: no arc length lives here
    last = i;
    if (s <= start + len) return glm::radians(glm::mix(offsets_[i], offsets_[i + 1], (s - start) / len));
    start += len;
  }
  return glm::radians(offsets_[last + 1]);  // s == Λ up to round-off
}

std::vector<double> TangentCurve::sample_tilt_spreads(int n) const {
  if (n < 1) throw std::invalid_argument("tangent sample count must be >= 1");
  std::vector<double> spreads(n);
  constexpr int kPoints = 256;  // midpoint rule over the arc; α is piecewise linear
  for (int k = 0; k < n; ++k) {
    const double a = k * total_ / n, width = total_ / n, centre = tilt_at((k + 0.5) * width);
    double sum = 0.0;
    for (int i = 0; i < kPoints; ++i) {
      const double d = tilt_at(a + (i + 0.5) * width / kPoints) - centre;
      sum += d * d;
    }
    spreads[k] = std::sqrt(sum / kPoints);
  }
  return spreads;
}

std::vector<double> TangentCurve::sample_tilts(int n) const {
  if (n < 1) throw std::invalid_argument("tangent sample count must be >= 1");
  std::vector<double> tilts(n);
  for (int k = 0; k < n; ++k) tilts[k] = tilt_at((k + 0.5) * total_ / n);
  return tilts;
}

}  // namespace weft
