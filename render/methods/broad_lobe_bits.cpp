#include "methods/broad_lobe_bits.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "methods/parallel_for.h"
#include "scene/vertex_pass_rows.h"

namespace weft {

std::vector<int> broad_lobe_slots(std::span<const SphericalGaussian> sgs) {
  std::vector<int> order;
  for (size_t k = 0; k < sgs.size(); ++k)
    if (sgs[k].sharpness < kBroadLobeSharpness) order.push_back(int(k));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sgs[a].sharpness < sgs[b].sharpness; });
  std::vector<int> slots(sgs.size(), -1);
  for (size_t s = 0; s < order.size() && s < size_t(kMaxBroadLobes); ++s) slots[order[s]] = int(s);
  return slots;
}

BroadLobeBits BroadLobeBits::all_open(size_t vertices) {
  BroadLobeBits out;
  out.vertices = vertices;
  out.words.assign(vertices * kBroadLobeWordsPerVertex, ~std::uint32_t(0));
  return out;
}

BroadLobeBits BroadLobeBits::compute(const VisibilityMask& mask, const TriangleMesh& mesh,
                                     std::span<const SphericalGaussian> sgs) {
  if (mask.vertex_count() != mesh.positions.size() || mesh.normals.size() != mesh.positions.size() ||
      mesh.warps.size() != mesh.positions.size())
    throw std::invalid_argument("broad lobe quadrature: the visibility mask holds " + std::to_string(mask.vertex_count()) +
                                " vertices, the mesh " + std::to_string(mesh.positions.size()) + " (with normals and warps)");
  BroadLobeBits out = all_open(mesh.positions.size());
  const std::vector<int> slots = broad_lobe_slots(sgs);
  // The cells' directions depend on the lighting only.
  std::vector<std::pair<int, std::vector<dvec3>>> cells;
  for (size_t k = 0; k < sgs.size(); ++k) {
    if (slots[k] < 0) continue;
    const SgWarpedGrid grid(sgs[k].axis, sgs[k].sharpness, kBroadLobeGrid);
    std::vector<dvec3> dirs;
    for (int i = 0; i < grid.polar(); ++i)
      for (int j = 0; j < grid.azimuthal(); ++j) dirs.push_back(grid.direction(i, j));
    cells.emplace_back(slots[k], std::move(dirs));
  }
  const int n = mask.resolution;
  // On a dense mesh only the pass vertices (scene/vertex_pass_mesh.h) are looked up; the others
  // take their heaviest corner's bits, as the bundle's mask rows there are.
  const VertexPassMesh& pass = pass_of(mesh);
  parallel_for(pass.vertices.empty() ? out.vertices : pass.vertices.size(), [&](size_t k) {
    const size_t v = pass.vertices.empty() ? k : pass.vertices[k];
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]);
    std::uint32_t* words = &out.words[v * kBroadLobeWordsPerVertex];
    for (const auto& [slot, dirs] : cells)
      for (size_t c = 0; c < dirs.size(); ++c) {
        const dvec3 l(glm::dot(dirs[c], f.u), glm::dot(dirs[c], f.v), glm::dot(dirs[c], f.n));
        if (l.z <= 0.0) continue;  // below the mask's hemisphere: left open (header)
        const int cell = hemisphere_cell_of(n, l);
        if (!mask.open(v, cell % n, cell / n))
          words[slot * kBroadLobeWordsPerSg + int(c) / 32] &= ~(std::uint32_t(1) << (c % 32));
      }
  });
  spread_from_pass_vertices(pass, out.words, kBroadLobeWordsPerVertex, false);
  return out;
}

}  // namespace weft
