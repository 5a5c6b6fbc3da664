// Point study of asymmetric tangent-sample counts on a scene (label bench; never in CI): the
// image error of 2+2, 1+2, 2+1 and 1+1 samples on pillow/linen/studio at grid-12 tables, measured
// as `weft bake --target-error` measures (the search's descent from 2+2 with a target every
// setting holds visits each). Linen's threads are identical; which of 1+2 and 2+1 errs more
// depends on how the warp lies (tests/methods/iwasaki_thread_symmetry_test.cpp). Prints a CSV.
// WEFT_BENCH_GRID sets the tables' grid (default 12), WEFT_BENCH_SCENE the scene (default pillow).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "bake/selection/scene_selection.h"
#include "support/scene_case.h"

using namespace weft;

TEST(SampleAsymmetry, LinenAtGrid12) {
  const std::string fabric = "linen_plain";
  const char* scene_name = std::getenv("WEFT_BENCH_SCENE");
  const test::SceneCase c = test::scene_in_fabric(scene_name ? scene_name : "pillow", fabric);
  SceneSelectionOptions o;
  o.target_error = 5.0;  // every setting holds: the descent measures each one-step-down setting
  o.cache = default_reference_cache();
  o.grid = std::getenv("WEFT_BENCH_GRID") ? std::atoi(std::getenv("WEFT_BENCH_GRID")) : 12;
  o.knobs.methods = {"iwasaki"};
  o.knobs.tangent_samples = {1, 2};
  o.knobs.level_strides = {1};
  o.knobs.svd_errors = {0.01};
  o.knobs.sdf_resolutions = {128};
  o.knobs.pca_errors = {0.01};
  o.log = [](const std::string& line) { std::fprintf(stderr, "  select: %s\n", line.c_str()); };
  const SceneSelection s = select_scene_settings(c.scene, c.fabrics, c.texts, c.sgs, o);
  std::printf("samples_thread1,samples_thread2,worst_view_relative_rmse,view_errors\n");
  for (const auto& m : s.tried) {
    std::string views;
    for (double e : m.view_errors) views += (views.empty() ? "" : " ") + std::to_string(e);
    std::printf("%d,%d,%.4f,%s\n", o.knobs.tangent_samples[m.setting.samples[0]],
                o.knobs.tangent_samples[m.setting.samples[1]], m.error, views.c_str());
  }
  EXPECT_GE(s.tried.size(), 3u);
}
