#include "bake/visibility/scene_visibility.h"

#include <atomic>
#include <chrono>

#include <omp.h>

#include "bake/visibility/visibility_sdf.h"
#include "reference/ray_scene.h"
#include "scene/vertex_pass_rows.h"

namespace weft {

std::optional<ObjectVisibility> bake_object_visibility(const Scene& scene, size_t object,
                                                       const SceneVisibilityOptions& opt,
                                                       const std::function<void(size_t, size_t)>& progress,
                                                       SceneVisibilityStats* stats) {
  const auto t0 = std::chrono::steady_clock::now();
  const TriangleMesh& mesh = scene.objects.at(object).mesh;
  if (mesh.warps.size() != mesh.positions.size())
    throw std::invalid_argument("visibility bake: object '" + scene.objects[object].name + "' has no warps");
  const RayScene rays(scene);
  const double eps = rays.ray_epsilon();
  const int n = opt.resolution, cells = n * n;
  const size_t vertices = mesh.positions.size();
  // Where the per-vertex passes shade a subset (scene/vertex_pass_mesh.h), only those vertices are
  // cast; the others take their corners' blend of the PCA coefficients (the SDF is linear in them).
  const VertexPassMesh& pass = pass_of(mesh);
  const size_t cast_vertices = pass.whole() ? vertices : pass.vertices.size();
  auto cast_vertex = [&](size_t k) { return pass.whole() ? k : size_t(pass.vertices[k]); };
  Eigen::MatrixXf sdfs(cells, Eigen::Index(cast_vertices));
  std::atomic<size_t> cast{0}, blocked{0}, done{0};
#pragma omp parallel for schedule(dynamic, 16)
  for (long k = 0; k < long(cast_vertices); ++k) {
    const size_t v = cast_vertex(size_t(k));
    const SurfaceFrame frame = SurfaceFrame::from_normal_warp(mesh.normals[v], mesh.warps[v]);
    const dvec3 origin = mesh.positions[v] + eps * frame.n;
    size_t c = 0, b = 0;
    const VertexSdf s = vertex_sdf(frame, origin, n, opt.supersample, [&](const dvec3& o, const dvec3& d) {
      ++c;
      const bool hit = !rays.unoccluded(o, d);  // as the reference's shadow rays
      b += hit;
      return hit;
    });
    for (int cell = 0; cell < cells; ++cell) sdfs(cell, k) = float(s.d.values[cell]);
    cast += c;
    blocked += b;
    const size_t now = ++done;
    if (progress && omp_get_thread_num() == 0) progress(now, cast_vertices);  // the callback need not be thread-safe
  }
  if (stats) {
    stats->vertices = cast_vertices;
    stats->blocked_share = cast ? double(blocked) / double(cast) : 0.0;
  }
  std::optional<ObjectVisibility> out;
  if (blocked > 0) {
    const SdfPca pca = fit_sdf_pca(sdfs, opt.pca);
    ObjectVisibility o;
    o.resolution = n;
    o.terms = pca.terms();
    o.mean.assign(pca.mean.data(), pca.mean.data() + cells);
    o.basis.resize(size_t(o.terms) * cells);
    for (int t = 0; t < o.terms; ++t)
      for (int k = 0; k < cells; ++k) o.basis[size_t(t) * cells + k] = pca.basis(k, t);
    // A column of coefficients per cast vertex (column-major: the rows, one after the other).
    o.coefficients.assign(pca.coefficients.data(), pca.coefficients.data() + cast_vertices * o.terms);
    if (!pass.whole()) o.coefficients = blended_rows(pass, o.coefficients, size_t(o.terms));
    o.rms_error = pca.rms_error;
    o.max_error = pca.max_error;
    out = std::move(o);
  }
  if (stats) stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace weft
