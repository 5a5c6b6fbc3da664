// The response calibration against a camera with known response: grey patches and paper cells
// spread over the card's share of the image, coded through sRGB with a curve β, vignetting v and
// per-photo scales, with sensor noise. The fit must give back β and v, and each photo's scale;
// a shadowed paper cell must not pull it off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "capture/response_calibration.h"

namespace {

struct Camera {
  double beta = 1.12, v = 0.10;
};

// IEC 61966-2-1's encoding, written out here so the test does not share the library's.
double srgb_encode(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

// A region of reflectance ρ at squared radius r2 (over the half diagonal), `pixels` pixels.
weft::ResponseSample region(const Camera& cam, const glm::dvec3& scale, double rho, double r2, std::mt19937& rng,
                            int pixels = 300, double shade = 1.0) {
  weft::ResponseSample s;
  s.reflectance = rho;
  s.r2 = r2;
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int i = 0; i < pixels; ++i) {
    std::array<std::uint8_t, 3> code;
    for (int c = 0; c < 3; ++c) {
      const double sensor = shade * scale[c] * rho * (1 - cam.v * r2);
      const double noisy = std::max(sensor + std::sqrt(sensor / 3000 + 4e-6) * noise(rng), 0.0);
      code[c] = static_cast<std::uint8_t>(std::lround(255 * srgb_encode(std::pow(noisy, 1 / cam.beta))));
    }
    s.add(code);
  }
  return s;
}

// One photo's samples: the six patches along the card's bottom, paper cells from the image's
// centre (r² 0.02) to the card's corners (r² 0.3), as a card filling the middle of the frame gives.
std::vector<weft::ResponseSample> photo(const Camera& cam, const glm::dvec3& scale, std::mt19937& rng) {
  std::vector<weft::ResponseSample> out;
  const double patches[] = {0.04, 0.09, 0.18, 0.32, 0.52, 0.80};
  for (int i = 0; i < 6; ++i) out.push_back(region(cam, scale, patches[i], 0.10 + 0.02 * std::abs(i - 2.5), rng));
  for (int i = 0; i < 40; ++i) out.push_back(region(cam, scale, 0.85, 0.02 + 0.28 * i / 39.0, rng));
  return out;
}

}  // namespace

TEST(CaptureResponse, SharedFitRecoversCurveVignettingAndScales) {
  const Camera cam;
  std::mt19937 rng(5);
  const std::vector<glm::dvec3> scales{{0.55, 0.52, 0.48}, {0.60, 0.58, 0.50}, {0.50, 0.49, 0.47}, {0.57, 0.55, 0.52}};
  std::vector<std::vector<weft::ResponseSample>> photos;
  for (const glm::dvec3& s : scales) photos.push_back(photo(cam, s, rng));
  const std::vector<weft::ResponseFit> fits = weft::fit_shared_response(photos);
  ASSERT_EQ(fits.size(), scales.size());
  for (size_t p = 0; p < fits.size(); ++p) {
    EXPECT_NEAR(fits[p].model.beta, cam.beta, 0.01);
    EXPECT_NEAR(fits[p].model.vignetting, cam.v, 0.02);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fits[p].model.scale[c] / scales[p][c], 1.0, 0.01) << "photo " << p << " channel " << c;
    EXPECT_EQ(fits[p].samples_used, 46);
  }
  // Through the fit, a cloth-like 0.3 reflectance in the image's centre reads within 1 %.
  std::mt19937 again(9);
  const weft::ResponseSample cloth = region(cam, scales[0], 0.3, 0.01, again, 2000);
  double sum = 0;
  for (int z = 0; z < 256; ++z) sum += cloth.histogram[1][z] * fits[0].model.sensor(static_cast<std::uint8_t>(z));
  EXPECT_NEAR(sum / cloth.count / ((1 - fits[0].model.vignetting * 0.01) * fits[0].model.scale[1]), 0.3, 0.003);
}

TEST(CaptureResponse, ShadowedPaperCellIsDropped) {
  const Camera cam;
  std::mt19937 rng(11);
  std::vector<std::vector<weft::ResponseSample>> photos;
  for (int p = 0; p < 3; ++p) photos.push_back(photo(cam, glm::dvec3(0.55, 0.52, 0.48), rng));
  // A shadow over two of the outermost paper cells of one photo: 40 % darker.
  photos[0][44] = region(cam, glm::dvec3(0.55, 0.52, 0.48), 0.85, 0.29, rng, 300, 0.6);
  photos[0][45] = region(cam, glm::dvec3(0.55, 0.52, 0.48), 0.85, 0.30, rng, 300, 0.6);
  const std::vector<weft::ResponseFit> fits = weft::fit_shared_response(photos);
  EXPECT_NEAR(fits[0].model.vignetting, cam.v, 0.02);
  EXPECT_EQ(fits[0].samples_used, 44);
  EXPECT_EQ(fits[1].samples_used, 46);
}

TEST(CaptureResponse, OnePhotoWithTooFewSamplesIsRefused) {
  const Camera cam;
  std::mt19937 rng(3);
  std::vector<std::vector<weft::ResponseSample>> photos{photo(cam, glm::dvec3(0.5), rng)};
  // Over-exposed: every sample clipped.
  photos.push_back(photo(cam, glm::dvec3(4.0), rng));
  EXPECT_THROW(weft::fit_shared_response(photos), std::runtime_error);
}
