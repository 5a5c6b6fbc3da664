// What the benchmarks of lighting-change work share (tests/methods/*_bench.cpp): the pillow's cloth
// with its visibility mask baked, and the median CPU and wall time of three runs.
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <optional>
#include <vector>

#include "bake/visibility/visibility_mask_bake.h"
#include "runtime/visibility_mask.h"
#include "scene/scene_file.h"

namespace weft::test {

struct PillowClothMask {
  Scene scene = load_scene_preset("pillow", WEFT_SOURCE_ASSETS "/scenes");
  size_t cloth = [this] {
    size_t c = 0;
    for (size_t i = 0; i < scene.objects.size(); ++i)
      if (scene.objects[i].material == Material::cloth) c = i;
    return c;
  }();
  std::optional<VisibilityMask> mask = bake_visibility_mask(scene, cloth, kMaskResolution);
  const TriangleMesh& mesh() const { return scene.objects[cloth].mesh; }
};

struct MedianTimes {
  double cpu_ms = 0.0;   // all threads of the process
  double wall_ms = 0.0;
};

// Runs `work` three times; the median of each clock.
template <class Work>
MedianTimes median_of_three(Work&& work) {
  auto process_cpu_ms = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
  };
  std::vector<double> cpu, wall;
  for (int i = 0; i < 3; ++i) {
    const double c0 = process_cpu_ms();
    const auto w0 = std::chrono::steady_clock::now();
    work();
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count());
    cpu.push_back(process_cpu_ms() - c0);
  }
  std::sort(cpu.begin(), cpu.end());
  std::sort(wall.begin(), wall.end());
  return {cpu[1], wall[1]};
}

}  // namespace weft::test
