// The turntable against closed forms: the camera circles the product's centre at a constant
// distance and height, keeps its view of it (the angle between the view and the product is
// unchanged), and half a turn mirrors it through the vertical there.
#include <gtest/gtest.h>

#include <cmath>

#include "kiosk/turntable.h"

using namespace weft;

namespace {
SceneObject box(Material material, glm::dvec3 lo, glm::dvec3 hi) {
  SceneObject o;
  o.material = material;
  o.mesh.positions = {lo, hi, {lo.x, hi.y, lo.z}};
  return o;
}
double view_angle(const Camera& c, const glm::dvec3& p) {
  return std::acos(glm::dot(glm::normalize(c.target - c.position), glm::normalize(p - c.position)));
}
}  // namespace

TEST(Turntable, PivotIsTheClothsCentreElseEveryObjects) {
  Scene s;
  s.objects.push_back(box(Material::lambertian, {-15, -15, 0}, {15, 15, 0}));  // a floor
  EXPECT_EQ(turntable_pivot(s), glm::dvec3(0, 0, 0));
  s.objects.push_back(box(Material::cloth, {1, 2, 0}, {3, 4, 1}));
  EXPECT_EQ(turntable_pivot(s), glm::dvec3(2, 3, 0.5));
  EXPECT_EQ(turntable_pivot(Scene{}), glm::dvec3(0.0));
}

TEST(Turntable, CirclesThePivotKeepingTheProductInView) {
  // A glTF-style camera: its target is a point one unit ahead, not the product.
  Camera c;
  c.position = {2, -2, 1.5};
  c.target = {2.1, -1, 1.4};
  c.up = glm::normalize(glm::dvec3(0.05, 0.1, 1.0));  // a glTF camera's up leans with its view
  const glm::dvec3 pivot{2, 3, 0.5};
  const double r = std::hypot(c.position.x - pivot.x, c.position.y - pivot.y);
  for (double deg : {0.0, 30.0, 90.0, 200.0, 359.0}) {
    const Camera t = turned_about_z(c, deg, pivot);
    EXPECT_NEAR(std::hypot(t.position.x - pivot.x, t.position.y - pivot.y), r, 1e-12) << deg;
    EXPECT_DOUBLE_EQ(t.position.z, c.position.z);
    EXPECT_NEAR(glm::length(t.target - t.position), glm::length(c.target - c.position), 1e-12);
    EXPECT_NEAR(view_angle(t, pivot), view_angle(c, pivot), 1e-9) << deg;
    // No roll: the up vector keeps its angle to the view and to the vertical.
    EXPECT_NEAR(glm::dot(t.up, glm::normalize(t.target - t.position)), glm::dot(c.up, glm::normalize(c.target - c.position)), 1e-12);
    EXPECT_NEAR(t.up.z, c.up.z, 1e-12);
  }
  const Camera half = turned_about_z(c, 180.0, pivot);
  EXPECT_NEAR(half.position.x, 2.0 * pivot.x - c.position.x, 1e-12);
  EXPECT_NEAR(half.position.y, 2.0 * pivot.y - c.position.y, 1e-12);
  EXPECT_NEAR(half.target.y, 2.0 * pivot.y - c.target.y, 1e-12);
}

TEST(Turntable, RefreshSharesBoundTheTurnBetweenRecomputations) {
  // Every vertex is recomputed within refresh_deg of turn: shares · turn ≤ refresh_deg, and the
  // next share count up would exceed it.
  for (double turn : {0.05, 0.4, 1.0, 1.5, 2.9}) {
    const int shares = refresh_shares(3.0, turn);
    EXPECT_LE(shares * turn, 3.0 + 1e-12) << turn;
    EXPECT_GT((shares + 1) * turn, 3.0) << turn;
  }
  EXPECT_EQ(refresh_shares(3.0, -0.4), refresh_shares(3.0, 0.4));  // either way round
  EXPECT_EQ(refresh_shares(3.0, 5.0), 1);                            // faster than the bound: every frame
  EXPECT_EQ(refresh_shares(0.0, 0.4), 1);                            // off
  EXPECT_EQ(refresh_shares(3.0, 0.0), kMaxRefreshShares);            // a still camera keeps its values
  EXPECT_EQ(refresh_shares(3.0, 0.01), kMaxRefreshShares);
}
