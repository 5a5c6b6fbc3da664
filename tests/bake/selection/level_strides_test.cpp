// The λ-level cuts the bake's search may take: exact (both ends kept), never under 3 levels.
#include <gtest/gtest.h>

#include "bake/selection/scene_selection.h"

namespace weft {
namespace {

TEST(LevelStrides, EveryExactCutOfAtLeastThreeLevelsCoarsestFirst) {
  EXPECT_EQ(level_strides_of(15), (std::vector<int>{7, 2, 1}));
  EXPECT_EQ(level_strides_of(9), (std::vector<int>{4, 2, 1}));
  EXPECT_EQ(level_strides_of(13), (std::vector<int>{6, 4, 3, 2, 1}));
  EXPECT_EQ(level_strides_of(3), (std::vector<int>{1}));
  EXPECT_EQ(level_strides_of(2), (std::vector<int>{1}));  // nothing to cut
}

TEST(LevelStrides, TheDefaultKnobsCutTheDefaultBake) {
  const int levels = BakeSettings{}.lambda_levels;
  for (int stride : SelectionKnobs{}.level_strides) {
    EXPECT_EQ((levels - 1) % stride, 0) << "stride " << stride;
    EXPECT_GE((levels - 1) / stride + 1, 3) << "stride " << stride;
  }
}

}  // namespace
}  // namespace weft
