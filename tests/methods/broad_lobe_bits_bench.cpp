// Benchmark (label bench): the cost of the broad lobes' cell bits at a lighting change
// (BroadLobeBits::compute, methods/iwasaki/broad_lobe_quadrature.h), pillow (mask baked at 64²)
// under the bench's 10 SGs fitted to sky:elev=5 and sky:elev=20. Prints the broad SGs, CPU time
// (all threads of the process) and wall time, median of 3, and the share of cells blocked.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <vector>

#include "bake/visibility_mask_bake.h"
#include "lighting/env_spec.h"
#include "lighting/sg_fit.h"
#include "methods/iwasaki/broad_lobe_quadrature.h"
#include "scene/scene.h"

using namespace weft;

namespace {

double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

TEST(BroadLobeBitsBench, PillowUnderSkies) {
  Scene scene = load_scene_preset("pillow", WEFT_SOURCE_ASSETS "/scenes");
  size_t cloth = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].material == Material::cloth) cloth = i;
  const auto mask = bake_visibility_mask(scene, cloth, kMaskResolution);
  ASSERT_TRUE(mask);
  const TriangleMesh& mesh = scene.objects[cloth].mesh;
  for (const char* env : {"sky:elev=5", "sky:elev=20"}) {
    const SgLighting sgs = fit_sgs(load_env(env, WEFT_SOURCE_ASSETS "/envmaps"), SgFitOptions{});
    const std::vector<int> slots = broad_lobe_slots(sgs);
    std::string broad;
    for (size_t k = 0; k < sgs.size(); ++k)
      if (slots[k] >= 0) broad += (broad.empty() ? "" : ", ") + std::to_string(sgs[k].sharpness).substr(0, 4);
    std::vector<double> cpu, wall;
    BroadLobeBits bits;
    for (int i = 0; i < 3; ++i) {
      const double c0 = process_cpu_ms();
      const auto w0 = std::chrono::steady_clock::now();
      bits = BroadLobeBits::compute(*mask, mesh, sgs);
      wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count());
      cpu.push_back(process_cpu_ms() - c0);
    }
    std::sort(cpu.begin(), cpu.end());
    std::sort(wall.begin(), wall.end());
    const int broad_count = int(std::count_if(slots.begin(), slots.end(), [](int x) { return x >= 0; }));
    size_t blocked = 0;
    for (size_t v = 0; v < bits.vertices; ++v)
      for (int w = 0; w < broad_count * kBroadLobeWordsPerSg; ++w) blocked += size_t(std::popcount(~bits.vertex(v)[w]));
    std::printf("pillow %s: %zu vertices, broad SGs (λ) %s: bits in %.2f ms CPU (all threads), %.2f ms wall; "
                "%.1f %% of the broad cells blocked\n",
                env, mesh.positions.size(), broad.c_str(), cpu[1], wall[1],
                100.0 * double(blocked) / double(std::max<size_t>(1, bits.vertices * size_t(broad_count) * kBroadLobeCells)));
  }
}

}  // namespace
