// The artefact measure (measure/detail_energy.h) against closed forms: a one-pixel checker keeps
// all its detail (a Gaussian of 2 px leaves nothing of it), a ramp has none (a symmetric blur keeps
// a linear function), and a checker patched into one block of a frame is that block's artefact.
#include "measure/detail_energy.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace weft;
using namespace weft::bench;

namespace {
Image grey(int w, int h, double (*value)(int, int)) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) im.at(x, y) = glm::dvec3(value(x, y));
  return im;
}
double checker(int x, int y) { return 0.5 + 0.1 * (((x + y) & 1) ? 1.0 : -1.0); }
double ramp(int x, int y) { return 0.2 + 0.004 * x + 0.002 * y; }
}  // namespace

TEST(DetailEnergy, AOnePixelCheckerIsAllDetailAndARampHasNone) {
  const DetailBlocks c = detail_energy(grey(96, 96, checker));
  ASSERT_EQ(c.columns, 3);
  ASSERT_EQ(c.rows, 3);
  EXPECT_NEAR(c.energy[4], 0.1 * 0.1, 1e-4);  // the middle block, away from the clamped edges
  const DetailBlocks r = detail_energy(grey(96, 96, ramp));
  EXPECT_LT(r.energy[4], 1e-12);
}

TEST(DetailRatio, APatchOfMoireInOneBlockIsFoundThereAlone) {
  const Image reference = grey(128, 96, ramp);
  EXPECT_LE(detail_ratio(reference, reference).worst, 1.0);
  EXPECT_EQ(detail_ratio(reference, reference).over, 0u);
  Image method = reference;
  for (int y = 40; y < 56; ++y)
    for (int x = 72; x < 88; ++x) method.at(x, y) += glm::dvec3(((x + y) & 1) ? 0.05 : -0.05);
  const DetailRatio d = detail_ratio(method, reference);
  EXPECT_EQ(d.blocks, 12u);
  EXPECT_EQ(d.over, 1u);
  EXPECT_EQ(d.worst_column, 2);
  EXPECT_EQ(d.worst_row, 1);
  EXPECT_GT(d.worst, 2.0);
  // The other way round (the frame smoother than its reference): no block over.
  EXPECT_EQ(detail_ratio(reference, method).over, 0u);
}

TEST(DetailRatio, RefusesImagesOfDifferentSizesOrNone) {
  EXPECT_THROW(detail_ratio(Image(64, 48), Image(48, 64)), std::invalid_argument);
  EXPECT_THROW(detail_energy(Image()), std::invalid_argument);
}
