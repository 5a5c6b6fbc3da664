// Benchmark (label bench): the cost of the broad lobes' cell bits at a lighting change
// (BroadLobeBits::compute, methods/iwasaki/broad_lobe_quadrature.h), pillow (mask baked at 64²)
// under the bench's 10 SGs fitted to sky:elev=5 and sky:elev=20. Prints the broad SGs, CPU time
// (all threads of the process) and wall time, median of 3, and the share of cells blocked.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <vector>

#include "lighting/env_spec.h"
#include "lighting/sg_fit.h"
#include "methods/iwasaki/broad_lobe_quadrature.h"
#include "scene/scene.h"
#include "support/lighting_change_bench.h"

using namespace weft;

namespace {

TEST(BroadLobeBitsBench, PillowUnderSkies) {
  const test::PillowClothMask pillow;
  ASSERT_TRUE(pillow.mask);
  const TriangleMesh& mesh = pillow.mesh();
  for (const char* env : {"sky:elev=5", "sky:elev=20"}) {
    const SgLighting sgs = fit_sgs(load_env(env, WEFT_SOURCE_ASSETS "/envmaps"), SgFitOptions{});
    const std::vector<int> slots = broad_lobe_slots(sgs);
    std::string broad;
    for (size_t k = 0; k < sgs.size(); ++k)
      if (slots[k] >= 0) broad += (broad.empty() ? "" : ", ") + std::to_string(sgs[k].sharpness).substr(0, 4);
    BroadLobeBits bits;
    const test::MedianTimes t = test::median_of_three([&] { bits = BroadLobeBits::compute(*pillow.mask, mesh, sgs); });
    const int broad_count = int(std::count_if(slots.begin(), slots.end(), [](int x) { return x >= 0; }));
    size_t blocked = 0;
    for (size_t v = 0; v < bits.vertices; ++v)
      for (int w = 0; w < broad_count * kBroadLobeWordsPerSg; ++w) blocked += size_t(std::popcount(~bits.vertex(v)[w]));
    std::printf("pillow %s: %zu vertices, broad SGs (λ) %s: bits in %.2f ms CPU (all threads), %.2f ms wall; "
                "%.1f %% of the broad cells blocked\n",
                env, mesh.positions.size(), broad.c_str(), t.cpu_ms, t.wall_ms,
                100.0 * double(blocked) / double(std::max<size_t>(1, bits.vertices * size_t(broad_count) * kBroadLobeCells)));
  }
}

}  // namespace
