// Study (label bench): would a cheaper quadrature of the broad lobes (broad_lobe_quadrature.h)
// hold the error? The lobe's light at a flat point (normal +z, warp +x) under one broad SG
// (λ uniform in [0.3, 3.9], axis and ω_o at random over 300 cases) by the rung's quadrature
// (kBroadLobeGrid cells a side, 16 tangent samples a thread: the bench's tables; a bundle bakes
// each fabric's own, the showroom's satin 15 + 1), against the same with fewer tangent samples
// or a coarser grid, and against a 32 grid (near converged in the cells).
// Prints the relative RMS per fabric preset. The run in docs/bench/kiosk_frame/README.md: fewer
// samples or cells hold on linen but not on the satin (its floats' narrow highlight needs every
// sample and cell), so the rung keeps both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/cloth_bsdf.h"
#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "methods/broad_lobe_bits.h"

using namespace weft;

namespace {
// broad_lobe_quadrature.cpp's sum over the SG-warped grid of n × 2n cells (every cell open), green channel.
double lobe(const ClothBsdf& bsdf, const dvec3& wo, const SphericalGaussian& g, int n) {
  const SurfaceFrame frame = SurfaceFrame::from_normal_warp(dvec3(0, 0, 1), dvec3(1, 0, 0));
  ClothBsdf::Point point = bsdf.at(frame);
  const SgWarpedGrid grid(g.axis, g.sharpness, n);
  double sum = 0.0;
  for (int i = 0; i < grid.polar(); ++i) {
    const double cos_t = grid.polar_cosine(i);
    for (int j = 0; j < grid.azimuthal(); ++j) {
      const dvec3 wi = grid.direction(cos_t, j);
      if (wi.z > 0.0) sum += point.integrand(wi, wo).g;
    }
  }
  return sum * grid.cell_weight();
}
}  // namespace

TEST(BroadLobeBudgetStudy, FewerSamplesOrCells) {
  struct Variant {
    const char* name;
    int samples, grid;
  };
  const Variant variants[] = {{"8 samples", 8, kBroadLobeGrid}, {"4 samples", 4, kBroadLobeGrid}, {"grid 6", 16, 6}, {"grid 4", 16, 4}};
  std::printf("%-28s %-10s %14s %14s\n", "fabric", "variant", "vs the rung", "vs grid 32");
  for (const char* name : {"linen_plain", "polyester_satin_charmeuse", "silk_shot", "velvet"}) {
    const Fabric f = load_fabric_preset(name, WEFT_SOURCE_ASSETS "/fabrics");
    const ClothBsdf full(f, 16);
    for (const Variant& v : variants) {
      const ClothBsdf bsdf(f, v.samples);
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      double d2 = 0, e2 = 0, s2 = 0, r2 = 0;
      for (int t = 0; t < 300; ++t) {
        const dvec3 wo = glm::normalize(dvec3(u(rng), u(rng), std::abs(u(rng)) + 0.05));
        const dvec3 axis = glm::normalize(dvec3(u(rng), u(rng), u(rng)));
        const SphericalGaussian g{axis, 0.3 + 1.8 * (1.0 + u(rng)), dvec3(1.0)};
        const double rung = lobe(full, wo, g, kBroadLobeGrid), converged = lobe(full, wo, g, 32), x = lobe(bsdf, wo, g, v.grid);
        d2 += (x - rung) * (x - rung);
        e2 += (x - converged) * (x - converged);
        r2 += (rung - converged) * (rung - converged);
        s2 += converged * converged;
      }
      std::printf("%-28s %-10s %13.2f%% %13.2f%%  (the rung itself: %.2f%%)\n", name, v.name, 100 * std::sqrt(d2 / s2),
                  100 * std::sqrt(e2 / s2), 100 * std::sqrt(r2 / s2));
      EXPECT_TRUE(std::isfinite(d2));
    }
  }
}
