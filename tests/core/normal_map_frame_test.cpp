// The normal map's frame rotation (core/normal_map_frame.h): a rotation, the one that takes n to
// n', that keeps the warp in the perturbed surface; seed 002's approximate MDF rotation (Eq. 9) as
// its special case for a tilt along the thread.
#include <gtest/gtest.h>

#include <random>

#include "core/normal_map_frame.h"

using namespace weft;

namespace {
SurfaceFrame random_frame(std::mt19937& rng) {
  std::normal_distribution<double> nd;
  const dvec3 n = glm::normalize(dvec3(nd(rng), nd(rng), nd(rng)));
  return SurfaceFrame::from_normal_warp(n, dvec3(nd(rng), nd(rng), nd(rng)));
}
void expect_near(dvec3 a, dvec3 b, double tol, const char* what) {
  EXPECT_NEAR(glm::length(a - b), 0.0, tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x
                                            << ", " << b.y << ", " << b.z << ")";
}
}  // namespace

TEST(NormalMapFrame, FlatTexelKeepsTheFrame) {
  std::mt19937 rng(3);
  const SurfaceFrame f = random_frame(rng);
  const SurfaceFrame g = normal_mapped_frame(f, tangent_space_normal(dvec3(0.5, 0.5, 1.0), 1.0));
  expect_near(g.n, f.n, 1e-12, "n");
  expect_near(g.u, f.u, 1e-12, "u");
  expect_near(g.v, f.v, 1e-12, "v");
}

TEST(NormalMapFrame, TangentSpaceNormalDecodesScalesAndRenormalizes) {
  expect_near(tangent_space_normal(dvec3(1.0, 0.5, 0.5), 1.0), dvec3(1, 0, kMinNormalMapZ) / std::hypot(1.0, kMinNormalMapZ),
              1e-12, "x, clamped z");
  const double h = kNormalMapHalfStep, x = (0.2 - h) / (1.0 - h);
  expect_near(tangent_space_normal(dvec3(0.6, 0.4, 0.9), 2.0), glm::normalize(dvec3(2 * x, -2 * x, 0.8)), 1e-12, "scaled");
  // An 8-bit map's flat codes, 127 and 128, are flat.
  for (double c : {127.0, 128.0}) expect_near(tangent_space_normal(dvec3(c / 255, c / 255, 1.0), 1.0), dvec3(0, 0, 1), 1e-12, "flat");
  // A mip level's average of two opposite tilts is short; it reads as the flat normal.
  expect_near(tangent_space_normal(dvec3(0.5, 0.5, 0.8), 1.0), dvec3(0, 0, 1), 1e-12, "short");
}

TEST(NormalMapFrame, RotationTakesNToNPrimeAndKeepsTheThreadsInTheSurface) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ud(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const SurfaceFrame f = random_frame(rng);
    const dvec3 t = tangent_space_normal(dvec3(ud(rng), ud(rng), 0.5 + 0.5 * ud(rng)), 1.0 + ud(rng));
    const SurfaceFrame g = normal_mapped_frame(f, t);
    expect_near(g.n, t.x * f.u + t.y * f.v + t.z * f.n, 1e-12, "n'");
    EXPECT_NEAR(glm::dot(g.u, g.n), 0.0, 1e-12);  // the warp lies in the perturbed surface
    EXPECT_NEAR(glm::length(g.u), 1.0, 1e-12);
    // A rotation: the frame keeps its handedness, and the axis n × n' stays where it was.
    EXPECT_NEAR(glm::dot(glm::cross(g.u, g.v), g.n), 1.0, 1e-12);
    const dvec3 axis = glm::cross(f.n, g.n);
    if (glm::length(axis) > 1e-6) {
      const dvec3 k = glm::normalize(axis);
      const dvec3 k_local(glm::dot(k, f.u), glm::dot(k, f.v), glm::dot(k, f.n));
      expect_near(k_local.x * g.u + k_local.y * g.v + k_local.z * g.n, k, 1e-12, "axis");
    }
    // The smallest rotation: u turns by no more than n does.
    EXPECT_LE(std::acos(std::clamp(glm::dot(f.u, g.u), -1.0, 1.0)),
              std::acos(std::clamp(glm::dot(f.n, g.n), -1.0, 1.0)) + 1e-9);
  }
}

TEST(NormalMapFrame, TiltAlongTheThreadIsSeed002sRotation) {
  // Seed 002, Eq. 9: R̃ takes the thread direction x to (ñ_z, 0, −ñ_x) in the unperturbed frame,
  // exact for a tilt along the thread (ñ_y = 0).
  const SurfaceFrame f;
  for (double a : {0.1, 0.4, 0.9}) {
    const dvec3 nt(std::sin(a), 0.0, std::cos(a));
    const SurfaceFrame g = normal_mapped_frame(f, nt);
    expect_near(g.u, dvec3(nt.z, 0.0, -nt.x), 1e-12, "R̃ x");
    expect_near(g.v, dvec3(0.0, 1.0, 0.0), 1e-12, "across");
  }
}
