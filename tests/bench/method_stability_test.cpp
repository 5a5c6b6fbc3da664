// Every runtime method's C++ evaluation under the stress cases of render/bench/stability.h
// (λ = 10⁴, a window strip of narrow SGs, grazing views to 89°, γ_s = 1°, velvet, back light, a sheer front-lit, back-lit and grazing,
// all-black and hot-texel environments): no NaN, no Inf, no negative radiance, alpha within [0, 1]. The all-black
// environment must give exactly 0. Errors against the reference are the bench's (report table).
#include <gtest/gtest.h>

#include "bench/stability.h"

using namespace weft;
using namespace weft::bench;

class MethodStability : public ::testing::TestWithParam<std::string> {};

TEST_P(MethodStability, FiniteAndNonNegativeUnderStress) {
  const CpuMethod* method = nullptr;
  for (const auto& m : cpu_methods())
    if (m.name == GetParam()) method = &m;
  ASSERT_NE(method, nullptr);
  for (const StressCase& c : stress_cases(WEFT_SOURCE_ASSETS "/fabrics", 150)) {
    const StressResult r = run_stress(*method, c, nullptr, 8);
    EXPECT_EQ(r.evaluations, 150);
    EXPECT_EQ(r.non_finite, 0) << GetParam() << " / " << c.name;
    EXPECT_EQ(r.negative, 0) << GetParam() << " / " << c.name;
    if (c.name == "all_black") EXPECT_EQ(r.max_abs, 0.0) << GetParam();
    else EXPECT_GT(r.max_abs, 0.0) << GetParam() << " / " << c.name << " lit nothing: the case would test nothing";
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, MethodStability, ::testing::Values("iwasaki", "mizutani", "sgpoint", "sheen", "mdfrot", "thin", "sheer"));

// The list the sweep runs is the list the bench reports: every CPU method is covered above.
TEST(MethodStability, CoversEveryCpuMethod) {
  std::vector<std::string> names;
  for (const auto& m : cpu_methods()) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"iwasaki", "mizutani", "sgpoint", "sheen", "mdfrot", "thin", "sheer"}));
}
