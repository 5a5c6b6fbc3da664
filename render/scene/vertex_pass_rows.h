#pragma once
// Per-vertex rows kept only at a pass mesh's vertices (scene/vertex_pass_mesh.h) and spread back
// to every mesh vertex: what the bundle stores of the visibility baked at the pass vertices alone.
// Rows that blend (an SDF's PCA coefficients) take their corners' blend; rows that do not (a
// mask's bits) take their heaviest corner's. Header-only: the kiosk's bundle reader uses it.
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "scene/vertex_pass_mesh.h"

namespace weft {

// The rows of the pass vertices (row k: mesh vertex pass.vertices[k]), `width` values each.
template <class T>
std::vector<T> pass_vertex_rows(const VertexPassMesh& pass, const std::vector<T>& rows, size_t width) {
  std::vector<T> out;
  out.reserve(pass.vertices.size() * width);
  for (uint32_t v : pass.vertices) out.insert(out.end(), rows.begin() + std::ptrdiff_t(v * width), rows.begin() + std::ptrdiff_t((v + 1) * width));
  return out;
}

// Every mesh vertex's row blended from its corners' (pass-vertex rows in): values of T (a float,
// or a glm vector), weighted in T's own precision.
template <class T>
struct RowScalar {
  using type = typename T::value_type;  // a glm vector's component
};
template <class T>
  requires std::is_arithmetic_v<T>
struct RowScalar<T> {
  using type = T;
};

template <class T>
std::vector<T> blended_rows(const VertexPassMesh& pass, const std::vector<T>& rows, size_t width) {
  using Scalar = typename RowScalar<T>::type;
  std::vector<T> out(pass.corners.size() * width);
  for (size_t v = 0; v < pass.corners.size(); ++v) {
    const auto& c = pass.corners[v];
    const glm::vec3 w = pass.weights[v];
    for (size_t i = 0; i < width; ++i)
      out[v * width + i] = Scalar(w.x) * rows[c[0] * width + i] + Scalar(w.y) * rows[c[1] * width + i] +
                           Scalar(w.z) * rows[c[2] * width + i];
  }
  return out;
}

// Which of a mesh vertex's three corners weighs most (the first of equals).
inline int heaviest_corner(const glm::vec3& w) { return w.x >= w.y && w.x >= w.z ? 0 : (w.y >= w.z ? 1 : 2); }

// Every mesh vertex's row as its heaviest corner's (pass-vertex rows in).
template <class T>
std::vector<T> heaviest_corner_rows(const VertexPassMesh& pass, const std::vector<T>& rows, size_t width) {
  std::vector<T> out(pass.corners.size() * width);
  for (size_t v = 0; v < pass.corners.size(); ++v) {
    const size_t from = pass.corners[v][size_t(heaviest_corner(pass.weights[v]))];
    std::copy_n(rows.begin() + std::ptrdiff_t(from * width), width, out.begin() + std::ptrdiff_t(v * width));
  }
  return out;
}

// Rows computed at the pass vertices alone, in place among every mesh vertex's (row v: mesh vertex
// v): each other vertex takes its corners' blend (`blend`: values that interpolate) or its
// heaviest corner's row (bits). What a lighting change does on a dense mesh: its per-vertex
// work at the pass vertices, the rest spread as the pass's values are.
template <class T>
void spread_from_pass_vertices(const VertexPassMesh& pass, std::vector<T>& rows, size_t width, bool blend) {
  if (pass.vertices.empty()) return;
  std::vector<bool> cast(pass.corners.size(), false);
  for (uint32_t v : pass.vertices) cast[v] = true;
  for (size_t v = 0; v < pass.corners.size(); ++v) {
    if (cast[v]) continue;
    const auto& c = pass.corners[v];
    const glm::vec3 w = pass.weights[v];
    if (!blend) {
      const size_t from = pass.vertices[c[size_t(heaviest_corner(w))]] * width;
      std::copy_n(rows.begin() + std::ptrdiff_t(from), width, rows.begin() + std::ptrdiff_t(v * width));
      continue;
    }
    const size_t a = pass.vertices[c[0]] * width, b = pass.vertices[c[1]] * width, d = pass.vertices[c[2]] * width;
    for (size_t i = 0; i < width; ++i) rows[v * width + i] = T(w.x * rows[a + i] + w.y * rows[b + i] + w.z * rows[d + i]);
  }
}

}  // namespace weft
