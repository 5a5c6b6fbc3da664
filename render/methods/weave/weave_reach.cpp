#include "methods/weave/weave_reach.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace weft {

namespace {
constexpr size_t kClusterVertices = 64;  // the bake orders vertices spatially: neighbours cluster

// The largest singular value of the 2×2 matrix [a b; c d].
double largest_stretch(double a, double b, double c, double d) {
  const double s = a * a + b * b + c * c + d * d, det = a * d - b * c;
  return std::sqrt(0.5 * (s + std::sqrt(std::max(s * s - 4.0 * det * det, 0.0))));
}

// The four planes of a frustum's sides and its near plane (a·x + b·y + c·z + d ≥ 0 inside), unit normals.
std::array<glm::dvec4, 5> frustum_planes(const glm::dmat4& m) {
  const glm::dvec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
      r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  std::array<glm::dvec4, 5> planes{r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2};
  for (auto& p : planes) p /= std::max(glm::length(glm::dvec3(p)), 1e-30);
  return planes;
}

bool outside(const std::array<glm::dvec4, 5>& planes, const glm::dvec3& c, double radius) {
  for (const auto& p : planes)
    if (glm::dot(glm::dvec3(p), c) + p.w < -radius) return true;
  return false;
}

// The distance from p to the circle through eye about the vertical through pivot.
double distance_to_orbit(const glm::dvec3& p, const glm::dvec3& eye, const glm::dvec3& pivot) {
  const double ring = glm::length(glm::dvec2(eye - pivot)), across = glm::length(glm::dvec2(p - pivot));
  return std::hypot(across - ring, p.z - eye.z);
}
}  // namespace

WeaveView weave_view(const Camera& camera, int width, int height) {
  WeaveView v;
  const double aspect = double(width) / std::max(height, 1);
  v.view_projection = glm::perspective(glm::radians(camera.fov_deg), aspect, 0.01, 1e7) *
                      glm::lookAt(camera.position, camera.target, camera.up);
  v.eye = camera.position;
  v.forward = glm::normalize(camera.target - camera.position);
  v.right = glm::normalize(glm::cross(v.forward, camera.up));
  v.up = glm::cross(v.right, v.forward);
  const double half_height = std::tan(glm::radians(camera.fov_deg) / 2.0), half_width = half_height * aspect;
  v.pixel = 2.0 * half_height / std::max(height, 1);
  v.corner_pixel = v.pixel / (1.0 + half_height * half_height + half_width * half_width);
  return v;
}

WeaveReach::WeaveReach(const TriangleMesh& mesh, std::span<const glm::dvec2> st, int rows)
    : positions_(mesh.positions), vertices_(mesh.positions.size()), first_triangle_(mesh.positions.size() + 1, 0) {
  if (st.size() != mesh.positions.size()) throw std::invalid_argument("weave reach: one weave coordinate per vertex needed");
  std::vector<uint32_t> mesh_triangle;  // each kept triangle's index in the mesh
  for (size_t ti = 0; ti < mesh.triangles.size(); ++ti) {
    const auto& t = mesh.triangles[ti];
    const glm::dvec3 e1 = mesh.positions[t[1]] - mesh.positions[t[0]], e2 = mesh.positions[t[2]] - mesh.positions[t[0]];
    // The triangle's plane coordinates: x along e1, y across it.
    const double l1 = glm::length(e1);
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double area2 = glm::length(normal);
    if (!(l1 > 0.0 && area2 > 1e-18 * l1 * l1)) continue;  // no area: no pixel
    const glm::dvec3 x = e1 / l1, y = glm::cross(normal / area2, x);
    const double p1x = l1, p2x = glm::dot(e2, x), p2y = glm::dot(e2, y);  // e1 = (p1x, 0), e2 = (p2x, p2y)
    const glm::dvec2 d1 = st[t[1]] - st[t[0]], d2 = st[t[2]] - st[t[0]];
    // J = [d1 d2]·P⁻¹, P = [[p1x p2x] [0 p2y]]: P⁻¹ = [[1/p1x, −p2x/(p1x·p2y)] [0, 1/p2y]].
    const double a = d1.x / p1x, b = (d2.x - d1.x * p2x / p1x) / p2y;
    const double c = d1.y / p1x, d = (d2.y - d1.y * p2x / p1x) / p2y;
    Triangle tri;
    tri.ds = double(rows) * (a * x + b * y);
    tri.dt = double(rows) * (c * x + d * y);
    tri.normal = normal / area2;
    tri.longest = std::max({l1, glm::length(e2), glm::length(e2 - e1)});
    triangles_.push_back(tri);
    mesh_triangle.push_back(uint32_t(ti));
    // Any view: a pixel's footprint on the surface is two vectors D = [Dx Dy] with σ_min(D) ≥ the
    // pixel's side (projecting onto the image never lengthens), so the longer of J·Dx and J·Dy is
    // at least σ_max(J)·side/√2.
    const double stretch = rows * largest_stretch(a, b, c, d) / std::sqrt(2.0);
    for (uint32_t v : t) {
      Vertex& out = vertices_[v];
      out.threads_per_metre = std::min(out.threads_per_metre, float(stretch));
      out.radius = std::max(out.radius, float(tri.longest));
      ++first_triangle_[v + 1];
    }
  }
  for (size_t v = 0; v < vertices_.size(); ++v) first_triangle_[v + 1] += first_triangle_[v];
  triangle_of_.resize(first_triangle_.back());
  std::vector<uint32_t> filled(first_triangle_.begin(), first_triangle_.end() - 1);
  for (size_t k = 0; k < triangles_.size(); ++k)
    for (uint32_t v : mesh.triangles[mesh_triangle[k]]) triangle_of_[filled[v]++] = uint32_t(k);
  for (size_t begin = 0; begin < vertices_.size(); begin += kClusterVertices) {
    Cluster c;
    c.begin = begin;
    c.end = std::min(begin + kClusterVertices, vertices_.size());
    glm::dvec3 lo = positions_[begin], hi = lo;
    c.threads_per_metre = std::numeric_limits<double>::infinity();
    for (size_t i = c.begin; i < c.end; ++i) {
      lo = glm::min(lo, positions_[i]);
      hi = glm::max(hi, positions_[i]);
      c.threads_per_metre = std::min(c.threads_per_metre, double(vertices_[i].threads_per_metre));
    }
    c.centre = 0.5 * (lo + hi);
    for (size_t i = c.begin; i < c.end; ++i)
      c.radius = std::max(c.radius, glm::length(positions_[i] - c.centre) + vertices_[i].radius);
    clusters_.push_back(c);
  }
}

double WeaveReach::vertex_footprint(size_t i, const WeaveView& view) const {
  const glm::dvec3 w = positions_[i] - view.eye;
  const double distance = glm::length(w), depth = glm::dot(w, view.forward);
  double best = std::numeric_limits<double>::infinity();
  if (!(depth > 0.0)) return best;
  const glm::dvec3 ray = w / distance;
  for (uint32_t k = first_triangle_[i]; k < first_triangle_[i + 1]; ++k) {
    const Triangle& t = triangles_[triangle_of_[k]];
    const double facing = glm::dot(t.normal, ray);
    if (std::abs(facing) < 1e-4) continue;  // edge-on: its footprint is endless
    double footprint = 0.0;
    for (const glm::dvec3& axis : {view.right, view.up}) {
      // A one-pixel step of the ray at this depth, carried along the ray onto the triangle's plane.
      const glm::dvec3 step = depth * view.pixel * axis, on_plane = step - (glm::dot(t.normal, step) / facing) * ray;
      footprint = std::max(footprint, glm::length(glm::dvec2(glm::dot(t.ds, on_plane), glm::dot(t.dt, on_plane))));
    }
    // The triangle's points come as near as the distance less its longest edge.
    best = std::min(best, footprint * std::max(distance - t.longest, 0.0) / distance);
  }
  return best;
}

double WeaveReach::nearest_footprint(const WeaveView& view) const {
  std::vector<float> each;
  return footprints(view, std::numeric_limits<double>::infinity(), each);
}

double WeaveReach::footprints(const WeaveView& view, double limit, std::vector<float>& out) const {
  const auto planes = frustum_planes(view.view_projection);
  out.assign(vertices_.size(), 1e30f);
  double best = std::numeric_limits<double>::infinity();
  for (const Cluster& c : clusters_) {
    if (outside(planes, c.centre, c.radius)) continue;
    if (c.threads_per_metre * std::max(glm::length(c.centre - view.eye) - c.radius, 0.0) * view.corner_pixel >= limit) continue;
    for (size_t i = c.begin; i < c.end; ++i) {
      if (outside(planes, positions_[i], vertices_[i].radius)) continue;
      const double f = vertex_footprint(i, view);
      out[i] = float(std::min(f, 1e30));
      best = std::min(best, f);
    }
  }
  return best;
}

double WeaveReach::nearest_footprint_orbiting(const glm::dvec3& eye, const glm::dvec3& pivot, double pixel) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Cluster& c : clusters_) {
    if (c.threads_per_metre * std::max(distance_to_orbit(c.centre, eye, pivot) - c.radius, 0.0) * pixel >= best) continue;
    for (size_t i = c.begin; i < c.end; ++i) {
      const Vertex& v = vertices_[i];
      if (!std::isfinite(v.threads_per_metre)) continue;
      best = std::min(best, v.threads_per_metre * std::max(distance_to_orbit(positions_[i], eye, pivot) - v.radius, 0.0) * pixel);
    }
  }
  return best;
}

}  // namespace weft
