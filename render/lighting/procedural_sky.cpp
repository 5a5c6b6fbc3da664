#include "lighting/procedural_sky.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace weft {

namespace {
using glm::dvec3;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// Perez et al.'s all-weather distribution F(θ, γ) = (1 + A e^{B/cos θ})(1 + C e^{Dγ} + E cos²γ).
struct Perez {
  double A, B, C, D, E;
  double operator()(double cos_theta, double gamma) const {
    const double c = std::max(cos_theta, 1e-4);
    const double cg = std::cos(gamma);
    return (1.0 + A * std::exp(B / c)) * (1.0 + C * std::exp(D * gamma) + E * cg * cg);
  }
};

// Preetham et al. 1999, Appendix A.2: the coefficients as linear functions of turbidity T.
Perez perez_Y(double T) {
  return {0.1787 * T - 1.4630, -0.3554 * T + 0.4275, -0.0227 * T + 5.3251, 0.1206 * T - 2.5771, -0.0670 * T + 0.3703};
}
Perez perez_x(double T) {
  return {-0.0193 * T - 0.2592, -0.0665 * T + 0.0008, -0.0004 * T + 0.2125, -0.0641 * T - 0.8989, -0.0033 * T + 0.0452};
}
Perez perez_y(double T) {
  return {-0.0167 * T - 0.2608, -0.0950 * T + 0.0092, -0.0079 * T + 0.2102, -0.0441 * T - 1.6537, -0.0109 * T + 0.0529};
}

// Zenith chromaticity: [T² T 1] · M · [θs³ θs² θs 1]ᵀ.
double zenith_chromaticity(const double (&m)[3][4], double T, double ts) {
  const double tv[3] = {T * T, T, 1.0};
  const double sv[4] = {ts * ts * ts, ts * ts, ts, 1.0};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) sum += tv[i] * m[i][j] * sv[j];
  return sum;
}
constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};

// CIE xyY → linear sRGB (D65 primaries), negatives clipped.
dvec3 xyY_to_rgb(double x, double y, double Y) {
  if (!(y > 1e-9) || !(Y > 0.0)) return dvec3(0.0);
  const double X = x * Y / y, Z = (1.0 - x - y) * Y / y;
  const dvec3 rgb(3.2406 * X - 1.5372 * Y - 0.4986 * Z, -0.9689 * X + 1.8758 * Y + 0.0415 * Z,
                  0.0557 * X - 0.2040 * Y + 1.0570 * Z);
  return glm::max(rgb, dvec3(0.0));
}

struct SkyModel {
  dvec3 sun;
  double theta_s;
  Perez fY, fx, fy;
  double Yz, xz, yz;  // zenith values
  double nY, nx, ny;  // F(0, θs): the zenith's own Perez value
  explicit SkyModel(const SkyParams& p) : sun(sun_direction(p)) {
    const double T = p.turbidity;
    theta_s = kPi / 2.0 - p.elevation_deg * kDeg;
    fY = perez_Y(T), fx = perez_x(T), fy = perez_y(T);
    const double chi = (4.0 / 9.0 - T / 120.0) * (kPi - 2.0 * theta_s);
    Yz = std::max(0.0, (4.0453 * T - 4.9710) * std::tan(chi) - 0.2155 * T + 2.4192);
    xz = zenith_chromaticity(kZenithX, T, theta_s);
    yz = zenith_chromaticity(kZenithY, T, theta_s);
    nY = fY(1.0, theta_s), nx = fx(1.0, theta_s), ny = fy(1.0, theta_s);
  }
  dvec3 operator()(const dvec3& d) const {
    const double gamma = std::acos(std::clamp(glm::dot(d, sun), -1.0, 1.0));
    const double c = d.z;
    return xyY_to_rgb(xz * fx(c, gamma) / nx, yz * fy(c, gamma) / ny, Yz * fY(c, gamma) / nY);
  }
};

// Kasten & Young 1989 relative optical air mass at apparent elevation h (degrees).
double air_mass(double h_deg) {
  const double h = std::max(h_deg, 0.0);
  return 1.0 / (std::sin(h * kDeg) + 0.50572 * std::pow(h + 6.07995, -1.6364));
}
}  // namespace

void validate(const SkyParams& p) {
  auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  if (!in(p.elevation_deg, 0.0, 90.0)) throw std::invalid_argument("elev: sun elevation must be within 0..90 degrees");
  if (!std::isfinite(p.azimuth_deg)) throw std::invalid_argument("azim: sun azimuth must be a finite angle in degrees");
  if (!(p.size_deg > 0.0 && p.size_deg <= 20.0))
    throw std::invalid_argument("size: sun angular diameter must be within (0, 20] degrees");
  if (!in(p.turbidity, 1.7, 10.0)) throw std::invalid_argument("haze: turbidity must be within 1.7..10");
  if (!in(p.ground_albedo, 0.0, 1.0)) throw std::invalid_argument("albedo: ground albedo must be within 0..1");
  if (p.width < 64 || p.width > 4096 || p.width % 4 != 0)
    throw std::invalid_argument("width: map width must be a multiple of 4 within 64..4096");
}

dvec3 sun_direction(const SkyParams& p) {
  const double e = p.elevation_deg * kDeg, a = p.azimuth_deg * kDeg;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

dvec3 sun_normal_irradiance(const SkyParams& p) {
  // Optical depths per unit air mass: Rayleigh at ~610/550/465 nm, and an aerosol term growing
  // with turbidity (T = 1 is a pure Rayleigh atmosphere).
  const dvec3 rayleigh(0.058, 0.098, 0.19);
  const double aerosol = 0.025 * (p.turbidity - 1.0);
  const double m = air_mass(p.elevation_deg);
  return 127.0 * glm::exp(-m * (rayleigh + dvec3(aerosol)));
}

dvec3 sun_radiance(const SkyParams& p) {
  const double r = 0.5 * p.size_deg * kDeg;
  return sun_normal_irradiance(p) / (kPi * std::sin(r) * std::sin(r));
}

dvec3 sky_radiance(const SkyParams& p, const dvec3& d) { return SkyModel(p)(d); }

EnvMap procedural_sky(const SkyParams& p) {
  validate(p);
  const int W = p.width, H = p.width / 2;
  EnvMap map(W, H);
  const SkyModel sky(p);
  const dvec3 sun = sky.sun;
  const dvec3 L_sun = sun_radiance(p);
  const double r = 0.5 * p.size_deg * kDeg;
  const double cos_r = std::cos(r);
  const double texel = kPi / H;  // a texel's angular height; its width is no larger away from the poles
  const double cos_reach = std::cos(std::min(kPi, r + 1.5 * texel));
  // Subsamples per texel side on the disc's edge: enough for a few across the disc's radius.
  const int n = std::clamp(static_cast<int>(std::ceil(8.0 * texel / r)), 16, 128);

  dvec3 horizontal(0.0);  // Σ Ω L cos θ over the upper hemisphere: what lights the ground
  for (int y = 0; y < H / 2; ++y) {
    const double omega = map.solid_angle(y);
    for (int x = 0; x < W; ++x) {
      const dvec3 d = map.direction(x, y);
      dvec3 L = sky(d);
      if (glm::dot(d, sun) >= cos_reach) {
        double inside = 0.0, total = 0.0;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            const glm::dvec2 uv((x + (i + 0.5) / n) / W, 1.0 - (y + (j + 0.5) / n) / H);
            const dvec3 s = uv_to_direction(uv);
            const double w = std::sqrt(std::max(0.0, 1.0 - s.z * s.z));  // solid angle ∝ cos(latitude)
            total += w;
            if (glm::dot(s, sun) >= cos_r) inside += w;
          }
        if (total > 0.0) L += L_sun * (inside / total);
      }
      map.at(x, y) = glm::vec3(L);
      horizontal += omega * L * d.z;
    }
  }
  const glm::vec3 ground(p.ground_albedo * horizontal / kPi);
  for (int y = H / 2; y < H; ++y)
    for (int x = 0; x < W; ++x) map.at(x, y) = ground;
  return map;
}

}  // namespace weft
