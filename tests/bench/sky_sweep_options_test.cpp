// `weft bench --sweep`'s preset (bench/sky_sweep.h): what it fills in, and what given options narrow.
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/sky_sweep.h"
#include "methods/registry.h"

using namespace weft;

TEST(SkySweepOptions, PresetRunsWeightingTableRungsOnThePillowAndDrape) {
  bench::BenchOptions o;
  o.sweep = "sky";
  bench::apply_sweep(o);
  EXPECT_EQ(o.scenes, (std::vector<std::string>{"pillow", "drape"}));
  EXPECT_EQ(o.envs, bench::sky_sweep_envs(false));
  EXPECT_EQ(o.target_error, 0.0);
  EXPECT_TRUE(o.no_stability);
  // Every rung drawn from the weighting tables is measured, and each is a registered method.
  for (const char* m : {"iwasaki", "iwasaki_vertex", "iwasaki_mask", "iwasaki_vertex_mask", "iwasaki_quadrature",
                        "iwasaki_vertex_quadrature", "iwasaki_mask_quadrature", "iwasaki_vertex_mask_quadrature"})
    EXPECT_NE(std::find(o.methods.begin(), o.methods.end(), m), o.methods.end()) << m;
  for (const auto& m : o.methods) EXPECT_NE(methods::find_method(m), nullptr) << m;
}

TEST(SkySweepOptions, GivenMethodsScenesAndEnvsNarrowThePreset) {
  bench::BenchOptions o;
  o.sweep = "sky";
  o.methods = {"iwasaki_mask_quadrature"};
  o.scenes = {"pillow"};
  o.envs = {"sky:elev=5"};
  bench::apply_sweep(o);
  EXPECT_EQ(o.methods, (std::vector<std::string>{"iwasaki_mask_quadrature"}));
  EXPECT_EQ(o.scenes, (std::vector<std::string>{"pillow"}));
  EXPECT_EQ(o.envs, (std::vector<std::string>{"sky:elev=5"}));
}

TEST(SkySweepOptions, UnknownPresetIsAnError) {
  bench::BenchOptions o;
  o.sweep = "skies";
  EXPECT_THROW(bench::apply_sweep(o), bench::InvalidOption);
}
