#include "scene/vertex_pass_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <utility>

#include <meshoptimizer.h>

#include "scene/vertex_pass_rows.h"

namespace weft {

namespace {

struct PassTriangles {
  std::vector<uint32_t> vertices;                   // mesh indices, ascending
  std::vector<std::array<uint32_t, 3>> triangles;   // mesh indices
};

// The simplifier's triangles at relative error `error` over `positions` (three floats a vertex).
PassTriangles simplified(const TriangleMesh& mesh, const std::vector<float>& positions, float error) {
  std::vector<uint32_t> indices;
  indices.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  std::vector<uint32_t> out(indices.size());
  const size_t n = meshopt_simplify(out.data(), indices.data(), indices.size(), positions.data(), mesh.positions.size(),
                                    3 * sizeof(float), 0, error, 0, nullptr);
  PassTriangles p;
  for (size_t i = 0; i + 2 < n; i += 3) p.triangles.push_back({out[i], out[i + 1], out[i + 2]});
  p.vertices.assign(out.begin(), out.begin() + std::ptrdiff_t(n));
  std::sort(p.vertices.begin(), p.vertices.end());
  p.vertices.erase(std::unique(p.vertices.begin(), p.vertices.end()), p.vertices.end());
  return p;
}

// The positions the simplifier sees for the edge bound: each vertex moved along its normal by a
// ripple of wavelength kRippleEdges × max_edge and kRippleAmplitude times the step's error (of the
// extent) in amplitude. The simplifier measures only geometry, and on a flat panel every collapse
// is free: it would leave triangles across the whole panel. Over the ripple a long collapse costs
// more than the step allows, so the triangles stay near the bound everywhere while curved parts
// still keep what they need; the pass vertices are the mesh's own (the ripple only steers which
// collapses are taken). Measured (a dense cushion, a flat sheet): 95 % of the edges within 0.94–1.05
// of the bound with these two; a longer ripple or a lower one leaves edges 2–4 times the bound.
constexpr double kRippleEdges = 2.0, kRippleAmplitude = 8.0;
std::vector<float> rippled(const TriangleMesh& mesh, double amplitude, double max_edge) {
  const double k = 2.0 * std::numbers::pi / (kRippleEdges * max_edge);
  std::vector<float> out;
  out.reserve(3 * mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 q = mesh.positions[v];
    const double h = std::isfinite(k) ? amplitude * (std::sin(k * q.x) + std::sin(k * q.y) + std::sin(k * q.z)) / 3.0 : 0.0;
    const glm::dvec3 r = q + h * mesh.normals[v];
    out.insert(out.end(), {float(r.x), float(r.y), float(r.z)});
  }
  return out;
}

// The point of triangle abc closest to p, as barycentric weights (Ericson, Real-Time Collision
// Detection §5.1.5).
glm::dvec3 closest_barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
  const double la = glm::length(a), lb = glm::length(b);
  if (!(la > 0) || !(lb > 0)) return 180.0;
  return glm::degrees(std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0)));
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = std::ptrdiff_t(std::min(v.size() - 1, size_t(q * double(v.size()))));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[size_t(k)];
}

// Every mesh vertex's three pass corners and weights: a kept vertex is its own; any other takes
// the pass triangle near it whose blended normal and warp are nearest its own (distance first:
// a thin part's other side is near in space, not in normal), found on a grid of cells two median
// edges wide.
VertexPassMesh blend_map(const TriangleMesh& mesh, const PassTriangles& p) {
  VertexPassMesh out;
  out.vertices = p.vertices;
  std::vector<uint32_t> pass_index(mesh.positions.size(), UINT32_MAX);
  for (size_t k = 0; k < p.vertices.size(); ++k) pass_index[p.vertices[k]] = uint32_t(k);
  std::vector<double> edges;
  for (const auto& t : p.triangles)
    for (int e = 0; e < 3; ++e) edges.push_back(glm::length(mesh.positions[t[e]] - mesh.positions[t[(e + 1) % 3]]));
  const double h = std::max(percentile(edges, 0.5), 1e-9);
  out.edge_p95 = percentile(edges, 0.95);
  out.edge_median = h;
  const double cell = 2.0 * h;
  auto key = [&](const glm::ivec3& c) { return (int64_t(c.x) * 73856093) ^ (int64_t(c.y) * 19349663) ^ (int64_t(c.z) * 83492791); };
  auto cell_of = [&](const glm::dvec3& x) { return glm::ivec3(glm::floor(x / cell)); };
  std::unordered_map<int64_t, std::vector<uint32_t>> grid;
  for (size_t t = 0; t < p.triangles.size(); ++t) {
    const auto& tri = p.triangles[t];
    glm::dvec3 lo = mesh.positions[tri[0]], hi = lo;
    for (int c = 1; c < 3; ++c) {
      lo = glm::min(lo, mesh.positions[tri[c]]);
      hi = glm::max(hi, mesh.positions[tri[c]]);
    }
    const glm::ivec3 a = cell_of(lo), b = cell_of(hi);
    for (int z = a.z; z <= b.z; ++z)
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) grid[key({x, y, z})].push_back(uint32_t(t));
  }
  const size_t n = mesh.positions.size();
  out.corners.resize(n);
  out.weights.resize(n);
  std::vector<double> normal_err(n, 0.0), warp_err(n, 0.0), gap(n, 0.0);
  std::vector<uint32_t> candidates;
  for (size_t v = 0; v < n; ++v) {
    if (pass_index[v] != UINT32_MAX) {
      out.corners[v] = {pass_index[v], pass_index[v], pass_index[v]};
      out.weights[v] = {1, 0, 0};
      continue;
    }
    const glm::dvec3 x = mesh.positions[v];
    double best = std::numeric_limits<double>::infinity();
    glm::dvec3 best_w(1, 0, 0);
    std::array<uint32_t, 3> best_t{0, 0, 0};
    for (int reach = 1; reach <= 8 && !std::isfinite(best); reach *= 2) {
      candidates.clear();
      const glm::ivec3 c = cell_of(x);
      for (int z = -reach; z <= reach; ++z)
        for (int y = -reach; y <= reach; ++y)
          for (int xx = -reach; xx <= reach; ++xx) {
            auto it = grid.find(key(c + glm::ivec3(xx, y, z)));
            if (it != grid.end()) candidates.insert(candidates.end(), it->second.begin(), it->second.end());
          }
      std::sort(candidates.begin(), candidates.end());
      candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
      for (uint32_t t : candidates) {
        const auto& tri = p.triangles[t];
        const glm::dvec3 w = closest_barycentric(x, mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
        const glm::dvec3 q = w.x * mesh.positions[tri[0]] + w.y * mesh.positions[tri[1]] + w.z * mesh.positions[tri[2]];
        const glm::dvec3 nb = w.x * mesh.normals[tri[0]] + w.y * mesh.normals[tri[1]] + w.z * mesh.normals[tri[2]];
        const glm::dvec3 ub = w.x * mesh.warps[tri[0]] + w.y * mesh.warps[tri[1]] + w.z * mesh.warps[tri[2]];
        const double ln = glm::length(nb), lu = glm::length(ub);
        const double cn = ln > 0 ? glm::dot(nb / ln, mesh.normals[v]) : -1.0, cu = lu > 0 ? glm::dot(ub / lu, mesh.warps[v]) : -1.0;
        const double score = glm::dot(x - q, x - q) / (h * h) + 4.0 * (1.0 - cn) + 2.0 * (1.0 - cu);
        if (score < best) {
          best = score;
          best_w = w;
          best_t = tri;
          gap[v] = glm::length(x - q);
          normal_err[v] = angle_deg(nb, mesh.normals[v]);
          warp_err[v] = angle_deg(ub, mesh.warps[v]);
        }
      }
    }
    if (!std::isfinite(best)) throw std::runtime_error("vertex pass mesh: a vertex with no pass triangle near it");
    out.corners[v] = {pass_index[best_t[0]], pass_index[best_t[1]], pass_index[best_t[2]]};
    out.weights[v] = glm::vec3(best_w);
  }
  out.normal_p95_deg = percentile(normal_err, 0.95);
  out.normal_p99_deg = percentile(normal_err, 0.99);
  out.normal_max_deg = n ? *std::max_element(normal_err.begin(), normal_err.end()) : 0.0;
  out.warp_p95_deg = percentile(warp_err, 0.95);
  out.warp_max_deg = n ? *std::max_element(warp_err.begin(), warp_err.end()) : 0.0;
  out.gap_p999 = percentile(gap, 0.999);
  out.gap_max = n ? *std::max_element(gap.begin(), gap.end()) : 0.0;
  return out;
}

// Within the budget: the angles, 95 % of the edges within 1.5 times the bound, and 99.9 % of the
// vertices within a quarter of the pass's long (95th percentile) edge of their blend points (no
// part of the surface left to a far triangle's corners; a few vertices where separate parts touch
// may lie farther, their normals still within the angles).
bool within(const VertexPassMesh& m, const VertexPassMeshOptions& o) {
  return m.edge_p95 <= 1.5 * o.max_edge && m.gap_p999 <= 0.25 * m.edge_p95 && m.normal_p95_deg <= o.normal_p95_deg &&
         m.warp_p95_deg <= o.warp_p95_deg && m.normal_p99_deg <= o.normal_p99_deg;
}

// The mesh's bounding box (lo, hi); the mesh has a vertex.
std::pair<glm::dvec3, glm::dvec3> bounds(const TriangleMesh& mesh) {
  glm::dvec3 lo = mesh.positions[0], hi = lo;
  for (const auto& q : mesh.positions) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  return {lo, hi};
}

}  // namespace

namespace {

// The ladder at one edge bound: the coarsest step within the budget, or whole (with the finest
// step's figures in kept_whole_because when that one is over it).
VertexPassMesh ladder(const TriangleMesh& mesh, const VertexPassMeshOptions& options, double extent) {
  const size_t n = mesh.positions.size();
  VertexPassMesh chosen;
  // Each step doubles the simplifier's error (relative to the mesh's extent): 0.0125 % … 6.4 %.
  for (float error = 0.000125f; error <= 0.0641f; error *= 2.0f) {
    const PassTriangles p = simplified(mesh, rippled(mesh, kRippleAmplitude * error * extent, options.max_edge), error);
    if (p.vertices.size() >= n || p.triangles.empty()) continue;
    if (!chosen.whole() && p.vertices == chosen.vertices) continue;  // this step removed nothing more
    VertexPassMesh m = blend_map(mesh, p);
    m.simplifier_error = error;
    if (!within(m, options)) {  // coarser steps only lose more
      if (chosen.whole()) {
        char why[256];
        std::snprintf(why, sizeof why,
                      "its finest step (%zu vertices) is over the budget: normals %.1f° (95 %%) / %.1f° (99 %%), "
                      "warps %.1f°, pass edges %.3g m against %.3g m, blend points %.3g m off (99.9 %%)",
                      p.vertices.size(), m.normal_p95_deg, m.normal_p99_deg, m.warp_p95_deg, m.edge_p95,
                      options.max_edge, m.gap_p999);
        chosen.kept_whole_because = why;
      }
      break;
    }
    chosen = std::move(m);
  }
  return chosen;
}

}  // namespace

VertexPassMesh vertex_pass_mesh(const TriangleMesh& mesh, const VertexPassMeshOptions& options) {
  VertexPassMesh whole;
  const size_t n = mesh.positions.size();
  if (n < options.keep_all_below || mesh.triangles.empty()) return whole;
  if (mesh.normals.size() != n || mesh.warps.size() != n)
    throw std::invalid_argument("vertex pass mesh: the mesh needs a normal and a warp per vertex");
  // The simplifier's error is relative to the mesh's extent: its bounding box's largest side.
  const auto [lo, hi] = bounds(mesh);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  // The view's bound steers the simplifier even at its finest step; where that step is already
  // over the budget (tight rounded corners between flat panels, far from the camera), shorter
  // edges follow the surface: the bound halved, three times at most, before keeping every vertex.
  VertexPassMeshOptions o = options;
  VertexPassMesh chosen = ladder(mesh, o, extent);
  for (int halving = 0; halving < 3 && chosen.whole() && !chosen.kept_whole_because.empty() && std::isfinite(o.max_edge);
       ++halving) {
    o.max_edge *= 0.5;
    VertexPassMesh finer = ladder(mesh, o, extent);
    if (!finer.whole() || !finer.kept_whole_because.empty()) chosen = std::move(finer);
  }
  return chosen;
}

std::string set_pass_meshes(Scene& scene, const std::string& report_prefix) {
  const char* every = std::getenv("WEFT_PASS_MESH");
  if (every && std::string(every) == "whole") return "";  // every vertex: for comparing
  for (auto& o : scene.objects) {
    if (!o.is_cloth() || o.mesh.positions.empty()) continue;
    const auto [lo, hi] = bounds(o.mesh);
    double nearest = std::numeric_limits<double>::infinity();
    auto view_from = [&](const glm::dvec3& eye) { nearest = std::min(nearest, glm::length(eye - glm::clamp(eye, lo, hi))); };
    view_from(scene.camera.position);
    if (scene.closeup) view_from(scene.closeup->position);
    VertexPassMeshOptions options;
    // An eye inside the box: the box's smallest side stands for the distance.
    const double d = nearest > 0 ? nearest : std::max(1e-3, std::min({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}));
    options.max_edge = d * std::tan(glm::radians(kPassEdgeDegrees));
    o.mesh.pass = std::make_shared<const VertexPassMesh>(vertex_pass_mesh(o.mesh, options));
  }
  return pass_mesh_report(scene, report_prefix);
}

std::string pass_mesh_report(const Scene& scene, const std::string& prefix) {
  std::string out;
  char line[160];
  for (const auto& o : scene.objects)
    if (o.mesh.pass && o.mesh.pass->whole() && !o.mesh.pass->kept_whole_because.empty())
      out += prefix + o.name + ": per-vertex passes on every one of " + std::to_string(o.mesh.positions.size()) +
             " vertices: " + o.mesh.pass->kept_whole_because + "\n";
    else if (o.mesh.pass && !o.mesh.pass->whole()) {
      std::snprintf(line, sizeof line, ": per-vertex passes on %zu of %zu vertices (blended normals within %.2f° and warps within %.2f° at 95 %%)\n",
                    o.mesh.pass->vertices.size(), o.mesh.positions.size(), o.mesh.pass->normal_p95_deg, o.mesh.pass->warp_p95_deg);
      out += prefix + o.name + line;
    }
  return out;
}

std::vector<glm::dvec3> blend_pass_values(const VertexPassMesh& pass, const std::vector<glm::dvec3>& pass_values) {
  if (pass.whole()) return pass_values;
  if (pass_values.size() != pass.vertices.size()) throw std::invalid_argument("blend_pass_values: a value per pass vertex");
  return blended_rows(pass, pass_values, 1);
}

}  // namespace weft
