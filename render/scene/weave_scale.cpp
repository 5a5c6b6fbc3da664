#include "scene/weave_scale.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/weave_layout.h"

namespace weft {

namespace {

// Triangle t's |∂P/∂u| and |∂P/∂v| and its weight, twice its UV area (0 where the UVs collapse).
struct UvStretch {
  glm::dvec2 length{0.0};
  double weight = 0.0;
};
UvStretch uv_stretch(const TriangleMesh& mesh, const std::array<uint32_t, 3>& t) {
  const glm::dvec3 e1 = mesh.positions[t[1]] - mesh.positions[t[0]], e2 = mesh.positions[t[2]] - mesh.positions[t[0]];
  const glm::dvec2 d1 = mesh.uvs[t[1]] - mesh.uvs[t[0]], d2 = mesh.uvs[t[2]] - mesh.uvs[t[0]];
  const double det = d1.x * d2.y - d1.y * d2.x;  // twice the triangle's signed UV area
  if (!(std::abs(det) > 1e-14)) return {};
  // [∂P/∂u ∂P/∂v] = [e1 e2] · [d1 d2]⁻¹
  const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
  return {glm::dvec2(glm::length(dpdu), glm::length(dpdv)), std::abs(det)};
}

// The area-weighted mean of the stretches summed in `sum` over `weight`; nullopt where there is none.
std::optional<glm::dvec2> mean_length(glm::dvec2 sum, double weight) {
  if (!(weight > 0.0) || !(sum.x > 0.0) || !(sum.y > 0.0) || !std::isfinite(sum.x) || !std::isfinite(sum.y))
    return std::nullopt;
  return sum / weight;
}

uint32_t root(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

glm::dvec2 uv_length(const TriangleMesh& mesh) {
  if (mesh.uvs.size() != mesh.positions.size()) return {1.0, 1.0};
  glm::dvec2 sum(0.0);
  double weight = 0.0;
  for (const auto& t : mesh.triangles) {
    const UvStretch s = uv_stretch(mesh, t);
    sum += s.weight * s.length;
    weight += s.weight;
  }
  return mean_length(sum, weight).value_or(glm::dvec2(1.0));
}

std::vector<glm::dvec2> weave_coordinates(const SceneObject& object, const Fabric& fabric) {
  const TriangleMesh& mesh = object.mesh;
  if (mesh.uvs.empty() || mesh.uvs.size() != mesh.positions.size()) return {};
  const glm::dvec2 object_tiles = weave_tiles_per_uv(object, fabric);
  std::vector<glm::dvec2> st(mesh.uvs.size());
  if (object.weave_repeats_per_uv.x > 0.0 && object.weave_repeats_per_uv.y > 0.0) {
    for (size_t v = 0; v < st.size(); ++v) st[v] = mesh.uvs[v] * object_tiles;
    return st;
  }
  // Islands: union–find over each triangle's vertices.
  std::vector<uint32_t> parent(mesh.positions.size());
  for (uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
  for (const auto& t : mesh.triangles) {
    const uint32_t a = root(parent, t[0]);
    parent[root(parent, t[1])] = a;
    parent[root(parent, t[2])] = a;
  }
  std::vector<glm::dvec2> sum(parent.size(), glm::dvec2(0.0));
  std::vector<double> weight(parent.size(), 0.0);
  for (const auto& t : mesh.triangles) {
    const UvStretch s = uv_stretch(mesh, t);
    const uint32_t r = root(parent, t[0]);
    sum[r] += s.weight * s.length;
    weight[r] += s.weight;
  }
  const glm::dvec2 repeat_m = weave_repeat_cm(fabric) / 100.0;
  for (size_t v = 0; v < st.size(); ++v) {
    const uint32_t r = root(parent, uint32_t(v));
    const std::optional<glm::dvec2> length = mean_length(sum[r], weight[r]);
    st[v] = mesh.uvs[v] * (length ? *length / repeat_m : object_tiles);
  }
  return st;
}

glm::dvec2 weave_tiles_per_uv(const SceneObject& object, const Fabric& fabric) {
  if (object.weave_repeats_per_uv.x > 0.0 && object.weave_repeats_per_uv.y > 0.0) return object.weave_repeats_per_uv;
  const glm::dvec2 repeat_m = weave_repeat_cm(fabric) / 100.0;
  return uv_length(object.mesh) / repeat_m;
}

bool weave_degenerate_uvs(glm::dvec2 st0, glm::dvec2 st1, glm::dvec2 st2) {
  const glm::dvec2 e1 = st1 - st0, e2 = st2 - st0, e3 = st2 - st1;
  const double longest = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
  const double area = std::abs(e1.x * e2.y - e1.y * e2.x);
  return !(longest > 1e-18) || !(area > 1e-4 * longest);
}

glm::dvec2 weave_repeat_metres(const SceneObject& object, const Fabric& fabric) {
  if (object.weave_repeats_per_uv.x > 0.0 && object.weave_repeats_per_uv.y > 0.0)
    return uv_length(object.mesh) / object.weave_repeats_per_uv;
  return weave_repeat_cm(fabric) / 100.0;
}

Camera closeup_camera(const Scene& scene, const std::map<std::string, Fabric>& fabrics, int height, double repeat_pixels) {
  if (scene.closeup) return *scene.closeup;
  double repeat = 0.0;
  for (const auto& o : scene.objects) {
    if (!o.is_cloth()) continue;
    const auto it = fabrics.find(o.fabric);
    if (it == fabrics.end()) continue;
    const glm::dvec2 r = weave_repeat_metres(o, object_fabric(o, it->second));
    const double smallest = std::min(r.x, r.y);
    if (repeat == 0.0 || smallest < repeat) repeat = smallest;
  }
  Camera c = scene.camera;
  const glm::dvec3 view = c.target - c.position;
  const double now = glm::length(view);
  if (repeat <= 0.0 || height < 1) return c;
  const double distance = repeat * height / (2.0 * repeat_pixels * std::tan(glm::radians(c.fov_deg) / 2.0));
  if (distance < now) c.position = c.target - view / now * distance;
  return c;
}

}  // namespace weft
