// Visibility driven by Embree: a vertex on a ground plane facing a wall sees the expected
// horizon, and its SDF changes sign there.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "bake/visibility/visibility_sdf.h"

using namespace weft;

namespace {

constexpr double kPi = std::numbers::pi;

// Ground quad z = 0 and a wall x = 1 (|y| ≤ 1000, 0 ≤ z ≤ 1), two triangles each.
class WallScene {
 public:
  WallScene() {
    device_ = rtcNewDevice(nullptr);
    scene_ = rtcNewScene(device_);
    add_quad({-1000, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {-1000, 1000, 0});
    add_quad({1, -1000, 0}, {1, 1000, 0}, {1, 1000, 1}, {1, -1000, 1});
    rtcCommitScene(scene_);
  }
  ~WallScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  bool occluded(const dvec3& o, const dvec3& d) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = float(o.x), ray.org_y = float(o.y), ray.org_z = float(o.z);
    ray.dir_x = float(d.x), ray.dir_y = float(d.y), ray.dir_z = float(d.z);
    ray.tnear = 0.0f;
    ray.tfar = std::numeric_limits<float>::infinity();
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0;  // Embree sets tfar = −∞ on a hit
  }

 private:
  void add_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4));
    for (int k = 0; k < 4; ++k) {
      const glm::vec3 p = std::array{a, b, c, d}[k];
      v[3 * k] = p.x, v[3 * k + 1] = p.y, v[3 * k + 2] = p.z;
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                                               RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 2));
    const unsigned tris[6] = {0, 1, 2, 0, 2, 3};
    std::copy(tris, tris + 6, idx);
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
  }
  RTCDevice device_;
  RTCScene scene_;
};

}  // namespace

TEST(EmbreeVisibility, WallGivesTheExpectedHorizon) {
  const WallScene scene;
  const SurfaceFrame frame;  // n = +z, u = +x (towards the wall), v = +y
  const dvec3 origin(0, 0, 1e-4);
  auto occluded = [&](const dvec3& o, const dvec3& d) { return scene.occluded(o, d); };
  const int n = 64;
  const double h = kPi / n;
  const VisibilityGrid vis = sample_visibility(frame, origin, n, occluded);
  // The wall of height 1 at distance 1 hides exactly the directions with ω·x > ω·z, i.e.
  // tan θ > cos φ in the vertex's angles (θ towards the wall, φ around it).
  int mismatches = 0, checked = 0;
  for (int i = 0; i < n; ++i)
    for (int j = n / 2; j < 3 * n / 2; ++j) {
      const double theta = cell_centre(-kPi / 2, h, i), phi = cell_centre(-kPi, h, j);
      const double margin = std::tan(theta) - std::cos(phi);
      if (std::abs(margin) < 1e-3) continue;  // grazing the wall's top edge
      ++checked;
      mismatches += (vis.at(i, j) == 1) != (margin < 0);
    }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(checked, n * n * 9 / 10);

  // The SDF straight towards the wall (φ ≈ 0) crosses zero at the wall's top, θ = π/4.
  const VertexSdf sdf = vertex_sdf(frame, origin, n, 1, occluded);
  const int j0 = n / 2;  // φ = +h/2
  for (int i = 0; i + 1 < n; ++i) {
    const double a = sdf.d.at(i, j0), b = sdf.d.at(i + 1, j0);
    if ((a > 0) != (b > 0)) {
      const double theta_a = cell_centre(-kPi / 2, h, i);
      const double crossing = theta_a + h * a / (a - b);
      EXPECT_NEAR(crossing, std::atan(std::cos(h / 2)), h / 2);
    }
  }
  // Far from the wall (grazing away from it) the horizon of the plane is what bounds d.
  EXPECT_NEAR(sdf.d.at(n / 4, n - 1), h / 2, 1e-9);
}
