#include "runtime/hemisphere_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace weft {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kQuarterPi = kPi / 4.0;
}  // namespace

glm::dvec3 hemisphere_from_square(glm::dvec2 s) {
  s = glm::clamp(s, glm::dvec2(-1.0), glm::dvec2(1.0));
  // Shirley–Chiu concentric map: square rings → disk rings of the same radius.
  double r = 0.0, phi = 0.0;
  if (s.x == 0.0 && s.y == 0.0) return {0.0, 0.0, 1.0};
  if (std::abs(s.x) > std::abs(s.y)) {
    r = s.x;
    phi = kQuarterPi * (s.y / s.x);
  } else {
    r = s.y;
    phi = 2.0 * kQuarterPi - kQuarterPi * (s.x / s.y);
  }
  const double dx = r * std::cos(phi), dy = r * std::sin(phi);
  const double r2 = r * r;
  // Lambert equal-area: disk radius² = 1 − z.
  const double scale = std::sqrt(std::max(0.0, 2.0 - r2));
  return {dx * scale, dy * scale, 1.0 - r2};
}

glm::dvec2 square_from_hemisphere(glm::dvec3 w) {
  if (!(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z))) return {0.0, 0.0};
  const double len = glm::length(w);
  if (len == 0.0) return {0.0, 0.0};
  w /= len;
  if (w.z < 0.0) {
    const double h = std::hypot(w.x, w.y);
    if (h == 0.0) return {1.0, 0.0};  // straight down: any horizon point; pick +x
    w = {w.x / h, w.y / h, 0.0};
  }
  const double r = std::sqrt(std::max(0.0, 1.0 - w.z));  // disk radius
  if (r == 0.0) return {0.0, 0.0};
  double phi = std::atan2(w.y, w.x);
  if (phi < -kQuarterPi) phi += 2.0 * kPi;
  double a, b;
  if (phi < kQuarterPi) {
    a = r;
    b = phi * a / kQuarterPi;
  } else if (phi < 3.0 * kQuarterPi) {
    b = r;
    a = -(phi - 2.0 * kQuarterPi) * b / kQuarterPi;
  } else if (phi < 5.0 * kQuarterPi) {
    a = -r;
    b = (phi - kPi) * a / kQuarterPi;
  } else {
    b = -r;
    a = -(phi - 6.0 * kQuarterPi) * b / kQuarterPi;
  }
  return glm::clamp(glm::dvec2(a, b), glm::dvec2(-1.0), glm::dvec2(1.0));
}

// A ring of the concentric square sits at disk radius r = max(|s_x|, |s_y|) = √(1 − z); the node
// square puts it at ρ with r = ρ·(b − (b − 1)ρ), b = 2 − a·π/4, so dθ/dρ is a·π/2 at the horizon
// (θ = 2·asin(r/√2) has dθ/dr = 2 there). Only the ring moves: s_y/s_x is kept. Square roots
// only, no asin: the GLSL twin must agree to float precision, and GPU asin is an approximation.
namespace {
constexpr double kRingB = 2.0 - kNodeRingHorizonSpacing * kQuarterPi;
}

glm::dvec3 hemisphere_from_node_square(glm::dvec2 s) {
  s = glm::clamp(s, glm::dvec2(-1.0), glm::dvec2(1.0));
  const double rho = std::max(std::abs(s.x), std::abs(s.y));
  return hemisphere_from_square(s * (kRingB - (kRingB - 1.0) * rho));  // r/ρ
}

glm::dvec2 node_square_from_hemisphere(glm::dvec3 w) {
  const glm::dvec2 s = square_from_hemisphere(w);
  const double r = std::max(std::abs(s.x), std::abs(s.y));
  // ρ/r from the smaller root of (b − 1)ρ² − bρ + r = 0, without cancellation at r → 0.
  const double rho_over_r = 2.0 / (kRingB + std::sqrt(std::max(0.0, kRingB * kRingB - 4.0 * (kRingB - 1.0) * r)));
  return glm::clamp(s * rho_over_r, glm::dvec2(-1.0), glm::dvec2(1.0));
}

glm::dvec3 HemisphereNodeGrid::node(int index) const {
  const int i = index % n, j = index / n;
  const double h = 2.0 / (n - 1);
  return hemisphere_from_node_square({-1.0 + h * i, -1.0 + h * j});
}

BilinearTap HemisphereNodeGrid::tap(const glm::dvec3& w) const {
  const glm::dvec2 s = node_square_from_hemisphere(w);
  const double x = (s.x + 1.0) * 0.5 * (n - 1), y = (s.y + 1.0) * 0.5 * (n - 1);
  const int i0 = std::clamp(static_cast<int>(std::floor(x)), 0, n - 2);
  const int j0 = std::clamp(static_cast<int>(std::floor(y)), 0, n - 2);
  const double fx = std::clamp(x - i0, 0.0, 1.0), fy = std::clamp(y - j0, 0.0, 1.0);
  const int k = j0 * n + i0;
  return {{k, k + 1, k + n, k + n + 1},
          {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy}};
}

glm::dvec3 HemisphereCellGrid::centre(int index) const {
  const int i = index % n, j = index / n;
  return hemisphere_from_square({-1.0 + (2.0 * i + 1.0) / n, -1.0 + (2.0 * j + 1.0) / n});
}

double HemisphereCellGrid::solid_angle() const { return 2.0 * kPi / (double(n) * n); }

}  // namespace weft
