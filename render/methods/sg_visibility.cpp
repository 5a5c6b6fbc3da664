#include "methods/sg_visibility.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "methods/parallel_for.h"
#include "scene/vertex_pass_rows.h"

namespace weft {

namespace {
// Zeroed values for `vertices` × the SGs, once `mesh` is known to have that many vertices, each with
// a normal and a warp (`what` names the baked data in the error).
SgVisibility sized_for(const char* what, size_t vertices, const TriangleMesh& mesh, const SgLighting& sgs) {
  if (mesh.positions.size() != vertices || mesh.normals.size() != vertices || mesh.warps.size() != vertices)
    throw std::invalid_argument(std::string(what) + " of " + std::to_string(vertices) + " vertices for a mesh of " +
                                std::to_string(mesh.positions.size()));
  SgVisibility out;
  out.vertices = vertices;
  out.sgs = int(sgs.size());
  out.values.assign(vertices * sgs.size() * 3, 0.0f);
  return out;
}
}  // namespace

SgVisibility SgVisibility::compute(const ObjectVisibility& o, const TriangleMesh& mesh, const SgLighting& sgs,
                                   bool above_horizon) {
  SgVisibility out = sized_for("visibility", o.vertex_count(), mesh, sgs);
  constexpr double kHalfPi = std::numbers::pi / 2;
  const int n = o.resolution, cells = n * n;
  const double h = std::numbers::pi / n;
  // The bundle stores the basis term-major ([term][cell]); a node's value reads one weight per
  // term, so the lookups below want it cell-major: transposed once per call (a few ms), the
  // reconstruction then reads 64 contiguous floats per node instead of 64 cache lines.
  std::vector<float> by_cell(size_t(cells) * o.terms);
  for (int t = 0; t < o.terms; ++t)
    for (int k = 0; k < cells; ++k) by_cell[size_t(k) * o.terms + t] = o.basis[size_t(t) * cells + k];
  // On a dense mesh only the pass vertices (scene/vertex_pass_mesh.h) are reconstructed; the
  // others take their corners' blend, as the pass's shading is blended (header).
  const VertexPassMesh& pass = pass_of(mesh);
  parallel_for(pass.vertices.empty() ? out.vertices : pass.vertices.size(), [&](size_t pk) {
    const size_t v = pass.vertices.empty() ? pk : pass.vertices[pk];
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]);
    const float* c = &o.coefficients[v * o.terms];
    // d at one node, from the PCA (clamped into the grid).
    auto d = [&](int i, int j) {
      const int k = std::clamp(i, 0, n - 1) * n + std::clamp(j, 0, n - 1);
      const float* b = &by_cell[size_t(k) * o.terms];
      double x = o.mean[k];
      for (int t = 0; t < o.terms; ++t) x += double(b[t]) * c[t];
      return x;
    };
    for (size_t k = 0; k < sgs.size(); ++k) {
      const dvec3 w = above_horizon ? weft::above_horizon(sgs[k], f.n, 0.0).axis : glm::normalize(sgs[k].axis);
      const double wu = std::clamp(glm::dot(w, f.u), -1.0, 1.0), wn = glm::dot(w, f.n), wv = glm::dot(w, f.v);
      const double theta_v = std::atan2(wu, std::sqrt(std::max(wn * wn + wv * wv, 1e-8))), phi_v = std::atan2(wv, wn);
      const double gi = std::clamp((theta_v + kHalfPi) / h - 0.5, 0.0, double(n - 1));
      const double gj = std::clamp((phi_v + kHalfPi) / h - 0.5, 0.0, double(n - 1));
      const int i0 = std::min(int(gi), n - 2), j0 = std::min(int(gj), n - 2);
      const double fi = gi - i0, fj = gj - j0;
      // d over the 4×4 nodes around the cell, each reconstructed once (12 of them are used).
      double memo[4][4];
      bool have[4][4] = {};
      auto dm = [&](int i, int j) {
        const int a = i - i0 + 1, b = j - j0 + 1;
        if (!have[a][b]) memo[a][b] = d(i, j), have[a][b] = true;
        return memo[a][b];
      };
      // (d, ∂d/∂θ', ∂d/∂φ') at a node: sdf_gradient's differences (central, one-sided at the edges).
      auto node = [&](int i, int j) {
        const int ia = std::max(i - 1, 0), ib = std::min(i + 1, n - 1), ja = std::max(j - 1, 0), jb = std::min(j + 1, n - 1);
        return dvec3(dm(i, j), (dm(ib, j) - dm(ia, j)) / ((ib - ia) * h), (dm(i, jb) - dm(i, ja)) / ((jb - ja) * h));
      };
      const dvec3 g = (1 - fi) * ((1 - fj) * node(i0, j0) + fj * node(i0, j0 + 1)) +
                      fi * ((1 - fj) * node(i0 + 1, j0) + fj * node(i0 + 1, j0 + 1));
      float* p = &out.values[(v * sgs.size() + k) * 3];
      p[0] = float(g.x), p[1] = float(g.y), p[2] = float(g.z);
    }
  });
  spread_from_pass_vertices(pass, out.values, sgs.size() * 3, true);
  return out;
}

SgVisibility SgVisibility::from_mask(const VisibilityMask& mask, const TriangleMesh& mesh, const SgLighting& sgs) {
  SgVisibility out = sized_for("visibility mask", mask.vertex_count(), mesh, sgs);
  const MaskDirections directions(mask.resolution);
  const VertexPassMesh& pass = pass_of(mesh);
  parallel_for(pass.vertices.empty() ? out.vertices : pass.vertices.size(), [&](size_t pk) {
    const size_t v = pass.vertices.empty() ? pk : pass.vertices[pk];
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]);
    for (size_t k = 0; k < sgs.size(); ++k) {
      const dvec3 a = glm::normalize(sgs[k].axis);
      out.values[(v * sgs.size() + k) * 3] =
          float(directions.sg_open_share(mask, v, dvec3(glm::dot(a, f.u), glm::dot(a, f.v), glm::dot(a, f.n)), sgs[k].sharpness));
    }
  });
  spread_from_pass_vertices(pass, out.values, sgs.size() * 3, true);
  return out;
}

}  // namespace weft
