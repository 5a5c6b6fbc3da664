#include "scene/mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "scene/bounds.h"
#include "scene/vertex_weld.h"

namespace weft {

namespace {
bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::dvec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

template <class V>
void check_finite(const std::vector<V>& values, const char* what, const std::string& name) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!finite(values[i]))
      throw MeshError("mesh '" + name + "': " + what + " of vertex " + std::to_string(i) + " is not finite (NaN/Inf)");
}
}  // namespace

MeshRepairReport repair_mesh(TriangleMesh& mesh, bool needs_uvs, const std::string& name) {
  const size_t nv = mesh.positions.size();
  if (nv == 0 || mesh.triangles.empty()) throw MeshError("mesh '" + name + "': no vertices or no triangles");
  if (needs_uvs && mesh.uvs.empty())
    throw MeshError("mesh '" + name + "': cloth needs UVs (the warp direction comes from them), none given");
  auto check_size = [&](size_t n, const char* what) {
    if (n != 0 && n != nv)
      throw MeshError("mesh '" + name + "': " + std::to_string(n) + " " + what + " for " + std::to_string(nv) +
                      " vertices");
  };
  check_size(mesh.normals.size(), "normals");
  check_size(mesh.uvs.size(), "UVs");
  check_size(mesh.warps.size(), "warp directions");
  check_finite(mesh.positions, "position", name);
  check_finite(mesh.normals, "normal", name);
  check_finite(mesh.uvs, "UV", name);

  const glm::dvec3 extent = bounds_of(mesh.positions).extent();
  const double diag2 = glm::dot(extent, extent);
  const double min_area2 = std::pow(1e-12 * diag2, 2);  // compares |cross|² (= 4·area²)

  MeshRepairReport report;
  std::vector<std::array<uint32_t, 3>> kept;
  kept.reserve(mesh.triangles.size());
  std::vector<bool> used(nv, false);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (uint32_t i : tri)
      if (i >= nv)
        throw MeshError("mesh '" + name + "': triangle " + std::to_string(t) + " uses vertex " + std::to_string(i) +
                        " of " + std::to_string(nv));
    const bool repeated = tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2];
    const glm::dvec3 c = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                    mesh.positions[tri[2]] - mesh.positions[tri[0]]);
    bool degenerate = repeated || glm::dot(c, c) <= min_area2;
    if (!degenerate && needs_uvs) {
      const glm::dvec2 e1 = mesh.uvs[tri[1]] - mesh.uvs[tri[0]], e2 = mesh.uvs[tri[2]] - mesh.uvs[tri[0]];
      degenerate = std::abs(e1.x * e2.y - e1.y * e2.x) <= 1e-14;
    }
    if (degenerate) {
      ++report.degenerate_triangles_dropped;
      continue;
    }
    kept.push_back(tri);
    for (uint32_t i : tri) used[i] = true;
  }
  if (kept.empty()) throw MeshError("mesh '" + name + "': every triangle is degenerate");
  mesh.triangles = std::move(kept);
  report.unused_vertices = static_cast<size_t>(std::count(used.begin(), used.end(), false));
  return report;
}

void compute_vertex_normals(TriangleMesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::dvec3(0.0));
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 c = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                    mesh.positions[t[2]] - mesh.positions[t[0]]);  // 2·area·n
    for (uint32_t i : t) mesh.normals[i] += c;
  }
  for (auto& n : mesh.normals) {
    const double l = glm::length(n);
    n = l > 0.0 ? n / l : glm::dvec3(0, 0, 1);  // unused vertices: any unit vector
  }
}

void compute_warp_directions(TriangleMesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size() || (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()))
    throw std::logic_error("compute_warp_directions: needs normals (and UVs for every vertex, if any)");
  std::vector<glm::dvec3> dpdu(mesh.positions.size(), glm::dvec3(0.0));
  for (const auto& t : mesh.triangles) {
    if (mesh.uvs.empty()) break;  // no UVs: every vertex takes the fixed tangent below
    const glm::dvec3 e1 = mesh.positions[t[1]] - mesh.positions[t[0]];
    const glm::dvec3 e2 = mesh.positions[t[2]] - mesh.positions[t[0]];
    const glm::dvec2 d1 = mesh.uvs[t[1]] - mesh.uvs[t[0]], d2 = mesh.uvs[t[2]] - mesh.uvs[t[0]];
    const double det = d1.x * d2.y - d1.y * d2.x;
    // Solve [e1 e2] = [dP/du dP/dv]·[d1 d2]: dP/du = (e1·d2.y − e2·d1.y)/det.
    glm::dvec3 t_u = (e1 * d2.y - e2 * d1.y) / det;
    const double area = 0.5 * glm::length(glm::cross(e1, e2));
    const double l = glm::length(t_u);
    if (!(l > 0.0) || !std::isfinite(l)) continue;
    for (uint32_t i : t) dpdu[i] += t_u / l * area;
  }
  // Where there is no usable dP/du, any tangent keeps the frame valid (the visibility bake and its
  // runtime lookup both read the frame from these warps).
  mesh.warps.resize(mesh.positions.size());
  for (size_t i = 0; i < dpdu.size(); ++i) mesh.warps[i] = unit_tangent(dpdu[i], mesh.normals[i]);
}

glm::dvec3 unit_tangent(const glm::dvec3& w, const glm::dvec3& n) {
  glm::dvec3 t = w - glm::dot(w, n) * n;
  if (!(glm::length(t) > 1e-6 * glm::length(w))) t = glm::cross(std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), n);
  t = glm::normalize(t);
  return glm::normalize(t - glm::dot(t, n) * n);
}

MeshRepairReport finish_mesh(TriangleMesh& mesh, bool is_cloth, const std::string& name) {
  const MeshRepairReport report = repair_mesh(mesh, is_cloth, name);
  if (mesh.normals.empty()) compute_vertex_normals(mesh);
  for (auto& n : mesh.normals) {
    const double l = glm::length(n);
    if (!(l > 0.0)) throw MeshError("mesh '" + name + "': a vertex normal has zero length");
    n /= l;
  }
  compute_warp_directions(mesh);
  return report;
}

void weld_vertices(TriangleMesh& mesh, double tolerance) {
  const bool has_uv = !mesh.uvs.empty();
  const std::vector<uint32_t> remap = welded_ids(mesh.positions, tolerance, glm::dvec3(0.0), mesh.uvs);
  TriangleMesh out;
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (remap[i] == out.positions.size()) {  // the first of its id
      out.positions.push_back(mesh.positions[i]);
      if (has_uv) out.uvs.push_back(mesh.uvs[i]);
    }
  for (auto& t : mesh.triangles)
    for (auto& i : t) i = remap[i];
  mesh.positions = std::move(out.positions);
  mesh.uvs = std::move(out.uvs);
  mesh.normals.clear();
  mesh.warps.clear();
}

}  // namespace weft
