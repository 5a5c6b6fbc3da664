#include "bake/visibility/visibility_mask_bake.h"

#include <atomic>
#include <stdexcept>

#include "core/microcylinder.h"
#include "reference/ray_scene.h"
#include "scene/vertex_pass_rows.h"

namespace weft {

std::optional<VisibilityMask> bake_visibility_mask(const Scene& scene, size_t object, int resolution) {
  if (resolution < 8 || resolution % 8) throw std::invalid_argument("visibility mask: resolution must be a multiple of 8");
  const TriangleMesh& mesh = scene.objects.at(object).mesh;
  if (mesh.warps.size() != mesh.positions.size())
    throw std::invalid_argument("visibility mask: object '" + scene.objects[object].name + "' has no warps");
  const RayScene rays(scene);
  VisibilityMask m;
  m.resolution = resolution;
  const size_t vertices = mesh.positions.size();
  std::vector<glm::dvec3> local(size_t(resolution) * resolution);
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) local[size_t(y) * resolution + x] = hemisphere_cell_direction(resolution, x, y);
  std::atomic<size_t> blocked{0};
  // Where the per-vertex passes shade a subset (scene/vertex_pass_mesh.h), only those vertices are
  // cast; each other vertex takes the mask of its heaviest corner (bits do not blend).
  const VertexPassMesh& pass = pass_of(mesh);
  const size_t cast_vertices = pass.whole() ? vertices : pass.vertices.size();
  m.words.assign(cast_vertices * size_t(m.blocks()), 0);  // a row per cast vertex
#pragma omp parallel for schedule(dynamic, 16)
  for (long k = 0; k < long(cast_vertices); ++k) {
    const long v = pass.whole() ? k : long(pass.vertices[size_t(k)]);
    const SurfaceFrame f = SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]);
    const glm::dvec3 origin = mesh.positions[v] + rays.ray_epsilon() * f.n;
    size_t b = 0;
    for (int y = 0; y < resolution; ++y)
      for (int x = 0; x < resolution; ++x) {
        const glm::dvec3 l = local[size_t(y) * resolution + x];
        if (rays.unoccluded(origin, l.x * f.u + l.y * f.v + l.z * f.n)) m.set_open(size_t(k), x, y);
        else ++b;
      }
    blocked += b;
  }
  if (blocked == 0) return std::nullopt;
  if (!pass.whole()) m.words = heaviest_corner_rows(pass, m.words, size_t(m.blocks()));
  return m;
}

}  // namespace weft
