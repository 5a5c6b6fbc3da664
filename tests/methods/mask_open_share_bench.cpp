// Benchmark (label bench): the cost of V_k per (vertex, SG) from the visibility masks at a
// lighting change (SgVisibility::from_mask), pillow (mask baked at 64²) under the bench's 10 SGs
// fitted to sky:elev=5 and sky:elev=20. Prints CPU time (all threads of the process) and wall
// time, median of 3, and how far the V_k lie from the exact cell sum over all 64² cells; and the
// weave layer's lights with their V (methods/weave/weave_lights.h) at the same change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "lighting/env_spec.h"
#include "lighting/sg_fit.h"
#include "methods/iwasaki/iwasaki_visibility.h"
#include "methods/sg_lighting_uniforms.h"
#include "methods/weave/weave_lights.h"
#include "runtime/visibility_mask.h"
#include "scene/scene.h"
#include "support/lighting_change_bench.h"

using namespace weft;

namespace {

// Σ bit·G / Σ G over every cell, in double: the share the mask holds exactly; −1 where G stays
// below e^{−14} of its peak over the whole hemisphere (the share is 1 by definition there).
double exact_share(const VisibilityMask& m, size_t vertex, const glm::dvec3& axis, double lambda) {
  double open = 0, all = 0, top = -1e300;
  for (int y = 0; y < m.resolution; ++y)
    for (int x = 0; x < m.resolution; ++x) {
      const double e = lambda * (glm::dot(hemisphere_cell_direction(m.resolution, x, y), axis) - 1.0);
      top = std::max(top, e);
      const double g = std::exp(e);
      all += g;
      if (m.open(vertex, x, y)) open += g;
    }
  return top < -14.0 ? -1.0 : open / all;
}

TEST(MaskOpenShareBench, PillowUnderSkies) {
  const test::PillowClothMask pillow;
  ASSERT_TRUE(pillow.mask);
  const VisibilityMask& mask = *pillow.mask;
  const TriangleMesh& mesh = pillow.mesh();
  for (const char* env : {"sky:elev=5", "sky:elev=20"}) {
    const SgLighting sgs = fit_sgs(load_env(env, WEFT_SOURCE_ASSETS "/envmaps"), SgFitOptions{});
    SgVisibility v;
    const test::MedianTimes t = test::median_of_three([&] { v = SgVisibility::from_mask(mask, mesh, sgs); });
    // Against the exact sum on every 97th vertex.
    double worst = 0, sum = 0;
    int n = 0;
    for (size_t vx = 0; vx < mesh.positions.size(); vx += 97) {
      const SurfaceFrame f = SurfaceFrame::from_normal_warp(mesh.normals[vx], mesh.warps[vx]);
      for (size_t k = 0; k < sgs.size(); ++k) {
        const glm::dvec3 a = glm::normalize(sgs[k].axis);
        const double want = exact_share(mask, vx, glm::dvec3(glm::dot(a, f.u), glm::dot(a, f.v), glm::dot(a, f.n)), sgs[k].sharpness);
        if (want < 0) continue;
        const double e = std::abs(v.at(vx, int(k)).x - want);
        if (e > worst && std::getenv("WEFT_BENCH_VERBOSE"))
          std::printf("  vertex %zu SG %zu (λ %.1f, axis z %.3f): %.4f, exact %.4f\n", vx, k, sgs[k].sharpness,
                      glm::dot(a, f.n), v.at(vx, int(k)).x, want);
        worst = std::max(worst, e), sum += e, ++n;
      }
    }
    std::printf("pillow %s: %zu vertices x %zu SGs: V_k in %.1f ms CPU (all threads), %.1f ms wall; "
                "against the exact cell sum (%d pairs): worst %.4f, mean %.5f\n",
                env, mesh.positions.size(), sgs.size(), t.cpu_ms, t.wall_ms, n, worst, sum / n);
    // The weave layer's lights at the same change: the broad lobes split, V per light.
    WeaveLighting w;
    const test::MedianTimes tw = test::median_of_three([&] { w = weave_lighting(sgs, gpu::kMaxSgs, &mask, nullptr, mesh); });
    std::printf("pillow %s: the weave layer's %zu lights and their V in %.1f ms CPU, %.1f ms wall\n", env, w.lights.size(),
                tw.cpu_ms, tw.wall_ms);
  }
}

}  // namespace
