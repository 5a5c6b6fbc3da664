// The broad lobes' quadrature (methods/iwasaki/broad_lobe_quadrature.h) on the flat linen swatch:
// its M × 2M SG-warped grid against the same quadrature at 32 × 64 (the reference's grid), the
// visibility mask's bits (all blocked, all open, one quadrant of the vertex frame open) against
// the reference's quadrature with the same visibility, and the split of a lighting at λ_b.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "bake/tables/weighting_bake.h"
#include "core/cloth_bsdf.h"
#include "methods/iwasaki/broad_lobe_quadrature.h"
#include "reference/sg_quadrature.h"
#include "runtime/visibility_mask.h"
#include "support/parity_bake_settings.h"
#include "support/sky_direction.h"

using namespace weft;
using test::at_elevation;

namespace {

// GridConvergesToTheFineGrid's measured worst at M = 8: linen 1.25 % (M = 4: 3.7 %); satin 21 %
// at λ = 0.5, 7–10 % at λ ≥ 1 (M = 4: 31–42 %): satin's float lobe is a sharp feature inside a
// broad SG at the grazing view. On the images M = 8 is enough (docs/research/iwasaki.md: drape/satin/sky:elev=5).
constexpr double kLinenQuadratureBound = 0.02;
constexpr double kSatinQuadratureBound = 0.25;
// Measured 0.6–0.8 %: the quadrature's part is within kQuadratureBound of the fine grid and
// iwasaki's at λ = 4 within ~10 % (docs/research/iwasaki.md); a lobe dropped or counted twice is off by 40–60 %.
constexpr double kSplitBound = 0.05;

const Fabric& linen() {
  static const Fabric f = load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics");
  return f;
}

double relative(const dvec3& a, const dvec3& b) { return glm::length(a - b) / glm::length(b); }

// One vertex at the origin with normal +z and warp +x, and a mask over its hemisphere whose cell
// (x, y) is open where `open(direction in (u, v, n))` holds at the cell's centre.
template <class Open>
VisibilityMask one_vertex_mask(const Open& open) {
  VisibilityMask m;
  m.resolution = kMaskResolution;
  m.words.assign(size_t(m.blocks()), 0);
  for (int y = 0; y < m.resolution; ++y)
    for (int x = 0; x < m.resolution; ++x)
      if (open(hemisphere_cell_direction(m.resolution, x, y))) m.set_open(0, x, y);
  return m;
}
TriangleMesh one_vertex() {
  TriangleMesh mesh;
  mesh.positions = {dvec3(0.0)};
  mesh.normals = {dvec3(0, 0, 1)};
  mesh.warps = {dvec3(1, 0, 0)};
  return mesh;
}

}  // namespace

// M = kBroadLobeGrid against M = 32 (the same quadrature, 16× the cells) for broad SGs overhead,
// low and partly below the horizon, at four views, on linen and on satin, whose narrow float lobe
// is the feature a coarse grid misses (M = 4, printed for comparison, is off by up to ~25 % on
// satin). The measured worst is asserted with a margin.
TEST(BroadLobeQuadrature, GridConvergesToTheFineGrid) {
  const SurfaceFrame frame;
  for (const char* fabric : {"linen_plain", "polyester_satin_charmeuse"}) {
    double worst = 0.0, worst_m4_all = 0.0;
    const ClothBsdf bsdf(load_fabric_preset(fabric, WEFT_SOURCE_ASSETS "/fabrics"), std::array<int, 2>{3, 3});
    for (double lambda : {0.5, 1.0, 2.0, 3.9}) {
      double worst_here = 0.0, worst_m4 = 0.0;
      for (double elevation : {70.0, 20.0, -10.0})
        for (const dvec3& view : {dvec3(0, 0, 1), dvec3(0.3, 0.2, 0.93), dvec3(-0.6, 0.3, 0.74), dvec3(0.2, -0.9, 0.3)}) {
          const SgLighting sgs = {{at_elevation(40, elevation), lambda, dvec3(1.0, 0.8, 0.6)}};
          const dvec3 wo = glm::normalize(view);
          SgQuadratureOptions fine, m4;
          fine.fixed_polar = 32, m4.fixed_polar = 4;
          fine.parallel = m4.parallel = false;
          const dvec3 ref = integrate_sg_lighting(bsdf, frame, wo, sgs, fine).radiance;
          const dvec3 got = broad_lobe_radiance(bsdf, frame, wo, sgs, broad_lobe_slots(sgs), {});
          worst_here = std::max(worst_here, relative(got, ref));
          worst_m4 = std::max(worst_m4, relative(integrate_sg_lighting(bsdf, frame, wo, sgs, m4).radiance, ref));
        }
      std::printf("%s λ = %.1f: M = %d worst relative difference %.2f %% (M = 4: %.2f %%)\n", fabric, lambda,
                  kBroadLobeGrid, 100 * worst_here, 100 * worst_m4);
      worst = std::max(worst, worst_here);
      worst_m4_all = std::max(worst_m4_all, worst_m4);
    }
    std::printf("%s: M = %d against M = 32: worst relative difference %.2f %%\n", fabric, kBroadLobeGrid, 100 * worst);
    EXPECT_GT(worst, 0.0);
    EXPECT_LT(worst, std::string(fabric) == "linen_plain" ? kLinenQuadratureBound : kSatinQuadratureBound) << fabric;
    EXPECT_LT(worst, 0.6 * worst_m4_all) << fabric << ": the grid does not converge";
  }
}

// The mask's bits: all blocked gives no broad light, all open exactly the unoccluded quadrature
// (the reference's on the same grid), a mask open on one quadrant of the vertex frame (u > 0,
// v > 0) the reference's quadrature with that mask's visibility (a direction is visible where its
// cell is open, hemisphere_cell_of; a few of the grid's directions lie in cells straddling the
// quadrant's edges), which also pins the mask's frame (u, v, n) to the vertex's normal and warp
// as the bake builds it.
TEST(BroadLobeQuadrature, MaskBitsGateTheCells) {
  const ClothBsdf bsdf(linen(), std::array<int, 2>{3, 3});
  const TriangleMesh mesh = one_vertex();
  const SurfaceFrame frame = SurfaceFrame::from_normal_warp(mesh.normals[0], mesh.warps[0]);
  const SgLighting sgs = {{at_elevation(40, 50), 1.0, dvec3(1.0)}, {at_elevation(250, 15), 2.5, dvec3(0.5, 0.6, 0.7)}};
  const std::vector<int> slots = broad_lobe_slots(sgs);
  const dvec3 wo = glm::normalize(dvec3(0.3, 0.2, 0.93));
  SgQuadratureOptions same_grid;
  same_grid.fixed_polar = kBroadLobeGrid;
  same_grid.parallel = false;

  const VisibilityMask blocked = one_vertex_mask([](const dvec3&) { return false; });
  const dvec3 none = broad_lobe_radiance(bsdf, frame, wo, sgs, slots, BroadLobeBits::compute(blocked, mesh, sgs).vertex(0));
  EXPECT_EQ(none, dvec3(0.0));

  const VisibilityMask open = one_vertex_mask([](const dvec3&) { return true; });
  const dvec3 all = broad_lobe_radiance(bsdf, frame, wo, sgs, slots, BroadLobeBits::compute(open, mesh, sgs).vertex(0));
  const dvec3 unoccluded = integrate_sg_lighting(bsdf, frame, wo, sgs, same_grid).radiance;
  EXPECT_GT(unoccluded.g, 0.0);
  EXPECT_LT(relative(all, unoccluded), 1e-12);

  auto quadrant = [](const dvec3& l) { return l.x > 0.0 && l.y > 0.0; };
  const VisibilityMask part = one_vertex_mask(quadrant);
  const dvec3 some = broad_lobe_radiance(bsdf, frame, wo, sgs, slots, BroadLobeBits::compute(part, mesh, sgs).vertex(0));
  SgQuadratureOptions shadowed = same_grid;
  shadowed.visible = [&](const dvec3& w) {
    const int cell = hemisphere_cell_of(part.resolution, dvec3(glm::dot(w, frame.u), glm::dot(w, frame.v), glm::dot(w, frame.n)));
    return part.open(0, cell % part.resolution, cell / part.resolution);
  };
  const dvec3 expected = integrate_sg_lighting(bsdf, frame, wo, sgs, shadowed).radiance;
  std::printf("quadrant open: %.6f of the unoccluded %.6f (green); reference %.6f\n", some.g, all.g, expected.g);
  EXPECT_GT(expected.g, 0.1 * all.g);
  EXPECT_LT(expected.g, 0.9 * all.g);
  EXPECT_LT(relative(some, expected), 1e-12);
}

// An SG just below λ_b goes to the quadrature and one at or above it to iwasaki; the two parts
// add up to iwasaki over the sharp SG plus the quadrature over the broad one, and the whole stays
// near the converged reference over both.
TEST(BroadLobeQuadrature, SplitAtTheBroadSharpness) {
  const BakeSettings settings = test::parity_bake_settings();
  const WeightingTables tables = bake_weighting_tables(linen(), settings);
  const ClothBsdf bsdf(linen(), settings.tangent_samples);
  const SurfaceFrame frame;
  const SphericalGaussian below{at_elevation(30, 55), kBroadLobeSharpness * (1.0 - 1e-9), dvec3(1.0, 0.9, 0.8)};
  const SphericalGaussian at{at_elevation(200, 35), kBroadLobeSharpness, dvec3(0.7, 0.8, 0.9)};
  const SgLighting sgs = {below, at};
  const std::vector<int> slots = broad_lobe_slots(sgs);
  ASSERT_EQ(slots, (std::vector<int>{0, -1}));
  for (const dvec3& view : {dvec3(0, 0, 1), dvec3(-0.6, 0.3, 0.74)}) {
    const dvec3 wo = glm::normalize(view);
    const dvec3 narrow = iwasaki_narrow_radiance(bsdf, tables, frame, wo, sgs, slots).radiance;
    const dvec3 broad = broad_lobe_radiance(bsdf, frame, wo, sgs, slots, {});
    const SgLighting only_at = {at}, only_below = {below};
    EXPECT_LT(relative(narrow, iwasaki_radiance(bsdf, tables, frame, wo, only_at).radiance), 1e-12);
    EXPECT_LT(relative(broad, broad_lobe_radiance(bsdf, frame, wo, only_below, std::vector<int>{0}, {})), 1e-12);
    const dvec3 ref = integrate_sg_lighting(bsdf, frame, wo, sgs).radiance;
    const double err = relative(narrow + broad, ref);
    std::printf("view (%.2f, %.2f, %.2f): split %.2f %% from the reference\n", wo.x, wo.y, wo.z, 100 * err);
    EXPECT_LT(err, kSplitBound);
  }
}
