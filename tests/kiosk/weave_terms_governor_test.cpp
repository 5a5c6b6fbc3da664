// The weave terms' governor (kiosk/weave_terms_governor.h): per pixel while the frames that show
// threads stay within the budget, the table once their median does not, and only in auto.
#include "kiosk/weave_terms_governor.h"

#include <gtest/gtest.h>

#include <limits>

namespace weft {
namespace {

using Mode = WeaveTermsGovernor::Mode;

TEST(WeaveTermsGovernor, ParsesTheThreeNamesAndNothingElse) {
  EXPECT_EQ(WeaveTermsGovernor::parse("auto"), Mode::automatic);
  EXPECT_EQ(WeaveTermsGovernor::parse("pixel"), Mode::pixel);
  EXPECT_EQ(WeaveTermsGovernor::parse("table"), Mode::table);
  EXPECT_FALSE(WeaveTermsGovernor::parse("Pixel"));
  EXPECT_FALSE(WeaveTermsGovernor::parse(""));
}

TEST(WeaveTermsGovernor, FallsBackToTheTableOnceTheMedianOfLayerFramesExceedsTheBudget) {
  WeaveTermsGovernor g(Mode::automatic, 40.0);
  EXPECT_TRUE(g.pixel_terms());
  // Slow frames that do not draw the layer (far away) are not the layer's doing.
  for (int k = 0; k < 50; ++k) EXPECT_FALSE(g.frame(500.0, false));
  EXPECT_TRUE(g.pixel_terms());
  // A hiccup or three among fast layer frames: the median stays within the budget.
  for (int k = 0; k < 5; ++k) EXPECT_FALSE(g.frame(30.0, true));
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(g.frame(900.0, true));
  EXPECT_TRUE(g.pixel_terms());
  // Then slow layer frames: the switch comes when most of the last kJudged are over budget.
  int switched_at = -1;
  for (int k = 0; k < WeaveTermsGovernor::kJudged; ++k)
    if (const auto line = g.frame(45.0, true)) {
      switched_at = k;
      EXPECT_NE(line->find("45 ms"), std::string::npos) << *line;
      EXPECT_NE(line->find("40 ms budget"), std::string::npos) << *line;
    }
  // After 5 fast + 3 hiccups the window holds 30 ×5, 900 ×3; its lower median (the 4th of 8
  // sorted) goes over 40 once two 45s replaced two 30s: 30 ×3, 45 ×2, 900 ×3.
  EXPECT_EQ(switched_at, 1);
  EXPECT_FALSE(g.pixel_terms());
  // For good: fast frames afterwards do not switch back, and say nothing.
  for (int k = 0; k < 20; ++k) EXPECT_FALSE(g.frame(5.0, true));
  EXPECT_FALSE(g.pixel_terms());
}

TEST(WeaveTermsGovernor, JudgesAFullWindowUnlessFarOverTheBudget) {
  // 2.5× the budget: only a full window decides.
  WeaveTermsGovernor g(Mode::automatic, 40.0);
  for (int k = 0; k + 1 < WeaveTermsGovernor::kJudged; ++k) EXPECT_FALSE(g.frame(100.0, true));
  EXPECT_TRUE(g.pixel_terms());
  EXPECT_TRUE(g.frame(100.0, true));
  EXPECT_FALSE(g.pixel_terms());
  // 25× (a software rasteriser): the first kEarly frames decide.
  WeaveTermsGovernor slow(Mode::automatic, 40.0);
  for (int k = 0; k + 1 < WeaveTermsGovernor::kEarly; ++k) EXPECT_FALSE(slow.frame(1000.0, true));
  EXPECT_TRUE(slow.frame(1000.0, true));
  EXPECT_FALSE(slow.pixel_terms());
}

TEST(WeaveTermsGovernor, AFixedChoiceIsKeptWhateverTheFramesCost) {
  WeaveTermsGovernor pixel(Mode::pixel, 40.0), table(Mode::table, 40.0);
  EXPECT_TRUE(pixel.pixel_terms());
  EXPECT_FALSE(table.pixel_terms());
  for (int k = 0; k < 30; ++k) {
    EXPECT_FALSE(pixel.frame(1000.0, true));
    EXPECT_FALSE(table.frame(1.0, true));
  }
  EXPECT_TRUE(pixel.pixel_terms());
  EXPECT_FALSE(table.pixel_terms());
}

TEST(WeaveTermsGovernor, ANonFiniteFrameTimeDoesNotSwitch) {
  WeaveTermsGovernor g(Mode::automatic, 40.0);
  for (int k = 0; k < 3 * WeaveTermsGovernor::kJudged; ++k) g.frame(std::numeric_limits<double>::quiet_NaN(), true);
  EXPECT_TRUE(g.pixel_terms());
}

}  // namespace
}  // namespace weft
