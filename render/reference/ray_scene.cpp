#include "reference/ray_scene.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

namespace weft {

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

RayScene::RayScene(const Scene& scene) : impl_(std::make_unique<Impl>()), scene_(scene) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw std::runtime_error("Embree: cannot create a device (error " +
                                               std::to_string(rtcGetDeviceError(nullptr)) + ")");
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const TriangleMesh& m = scene.objects[o].mesh;
    RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), m.positions.size()));
    for (size_t i = 0; i < m.positions.size(); ++i) {
      for (int c = 0; c < 3; ++c) v[3 * i + c] = static_cast<float>(m.positions[i][c]);
      lo = glm::min(lo, m.positions[i]);
      hi = glm::max(hi, m.positions[i]);
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), m.triangles.size()));
    for (size_t t = 0; t < m.triangles.size(); ++t)
      for (int c = 0; c < 3; ++c) idx[3 * t + c] = m.triangles[t][c];
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(impl_->scene, g);
    rtcReleaseGeometry(g);
    if (id != o) throw std::logic_error("Embree: unexpected geometry id");
  }
  rtcCommitScene(impl_->scene);
  // Single-precision BVH: offsets must exceed float rounding at the scene's scale.
  epsilon_ = 2e-5 * std::max(1.0, glm::length(hi - lo));
}

RayScene::~RayScene() = default;

std::optional<RayHit> RayScene::intersect(const glm::dvec3& origin, const glm::dvec3& dir) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh{};
  rh.ray.org_x = float(origin.x), rh.ray.org_y = float(origin.y), rh.ray.org_z = float(origin.z);
  rh.ray.dir_x = float(dir.x), rh.ray.dir_y = float(dir.y), rh.ray.dir_z = float(dir.z);
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return RayHit{rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar};
}

bool RayScene::unoccluded(const glm::dvec3& origin, const glm::dvec3& dir, double t_near) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r{};
  r.org_x = float(origin.x), r.org_y = float(origin.y), r.org_z = float(origin.z);
  r.dir_x = float(dir.x), r.dir_y = float(dir.y), r.dir_z = float(dir.z);
  r.tnear = float(t_near);
  r.tfar = std::numeric_limits<float>::infinity();
  r.mask = ~0u;
  rtcOccluded1(impl_->scene, &ctx, &r);
  return r.tfar >= 0.0f;  // Embree sets tfar = −∞ on a hit
}

SurfacePoint RayScene::surface(const RayHit& hit) const {
  const TriangleMesh& m = scene_.objects[hit.object].mesh;
  const auto& t = m.triangles[hit.triangle];
  const double b0 = 1.0 - hit.b1 - hit.b2;
  SurfacePoint s;
  const glm::dvec3 &p0 = m.positions[t[0]], &p1 = m.positions[t[1]], &p2 = m.positions[t[2]];
  s.position = b0 * p0 + hit.b1 * p1 + hit.b2 * p2;
  s.geometric_normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  s.normal = glm::normalize(b0 * m.normals[t[0]] + hit.b1 * m.normals[t[1]] + hit.b2 * m.normals[t[2]]);
  if (!m.warps.empty()) s.warp = b0 * m.warps[t[0]] + hit.b1 * m.warps[t[1]] + hit.b2 * m.warps[t[2]];
  else s.warp = glm::dvec3(0.0);
  if (!m.uvs.empty()) s.uv = b0 * m.uvs[t[0]] + hit.b1 * m.uvs[t[1]] + hit.b2 * m.uvs[t[2]];
  return s;
}

}  // namespace weft
