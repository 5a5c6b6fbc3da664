#include "scene/procedural_meshes.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace weft {

using glm::dvec3;
constexpr double kPi = std::numbers::pi;

TriangleMesh parametric_grid(int nu, int nv, const std::function<dvec3(double, double)>& position, bool flip) {
  TriangleMesh m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double s = double(i) / nu, t = double(j) / nv;
      m.positions.push_back(position(s, t));
      m.uvs.emplace_back(s, t);
    }
  auto at = [&](int i, int j) { return static_cast<uint32_t>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      std::array<uint32_t, 3> a{at(i, j), at(i + 1, j), at(i + 1, j + 1)};
      std::array<uint32_t, 3> b{at(i, j), at(i + 1, j + 1), at(i, j + 1)};
      if (flip) {
        std::swap(a[1], a[2]);
        std::swap(b[1], b[2]);
      }
      m.triangles.push_back(a);
      m.triangles.push_back(b);
    }
  return m;
}

TriangleMesh swatch_mesh(double size, int resolution) {
  return parametric_grid(resolution, resolution, [&](double s, double t) {
    return dvec3((s - 0.5) * size, (t - 0.5) * size, 0.0);
  });
}

TriangleMesh quad_mesh(double size_x, double size_y) {
  TriangleMesh m = parametric_grid(1, 1, [&](double s, double t) {
    return dvec3((s - 0.5) * size_x, (t - 0.5) * size_y, 0.0);
  });
  m.uvs.clear();
  return m;
}

std::vector<double> graded_axis(double size, double fine_size, double spacing, double growth) {
  const double half = 0.5 * size, fine_half = std::min(0.5 * fine_size, half);
  std::vector<double> right;  // ticks > 0 up to the edge, the fine centre's first
  const int fine_cells = std::max(1, int(std::ceil(fine_half / spacing - 1e-9)));
  for (int i = 1; i <= fine_cells; ++i) right.push_back(fine_half * i / fine_cells);
  double step = fine_half / fine_cells;
  while (right.back() < half) {
    step *= growth;
    const double next = right.back() + step;
    // The last cell ends at the edge; one that would be under half a step is merged.
    if (next >= half || half - next < 0.5 * step * growth) {
      right.push_back(half);
      break;
    }
    right.push_back(next);
  }
  std::vector<double> axis;
  for (auto it = right.rbegin(); it != right.rend(); ++it) axis.push_back(-*it);
  axis.push_back(0.0);
  axis.insert(axis.end(), right.begin(), right.end());
  return axis;
}

TriangleMesh graded_quad_mesh(double size_x, double size_y, double fine_size, double spacing, double growth) {
  const std::vector<double> xs = graded_axis(size_x, fine_size, spacing, growth);
  const std::vector<double> ys = graded_axis(size_y, fine_size, spacing, growth);
  const int nu = int(xs.size()) - 1, nv = int(ys.size()) - 1;
  // parametric_grid's (s, t) = (i/nu, j/nv): back to the tick indices.
  TriangleMesh m = parametric_grid(nu, nv, [&](double s, double t) {
    return dvec3(xs[size_t(std::lround(s * nu))], ys[size_t(std::lround(t * nv))], 0.0);
  });
  m.uvs.clear();  // a floor, as quad_mesh
  return m;
}

TriangleMesh pillow_mesh(double size_x, double size_y, double height, double wrinkle, int resolution) {
  // (σ,τ) ∈ [−1,1]²; f = ((1−σ²)(1−τ²))^0.45 is the stuffing profile, 0 on the seam.
  const double half = 0.5 * height;
  auto sheet = [&](bool top) {
    return [=](double s, double t) {
      const double sg = 2 * s - 1, tg = 2 * t - 1;
      const double f = std::pow(std::max(0.0, (1 - sg * sg) * (1 - tg * tg)), 0.45);
      // Seams pinch inward between the corners, as a stuffed cushion's do.
      const double x = 0.5 * size_x * sg * (1.0 - 0.10 * (1 - tg * tg));
      const double y = 0.5 * size_y * tg * (1.0 - 0.10 * (1 - sg * sg));
      // Wrinkles radiate in from the seam: strongest mid-way between seam and crown.
      const double angle = std::atan2(tg * size_y, sg * size_x);
      const double w = wrinkle * f * (1 - f) * 4.0 * std::sin(9.0 * angle + 1.3) * (top ? 1.0 : 0.4);
      // The bottom sheet is flattened by the pillow's weight; the seam floats at `base`.
      const double base = 0.32 * height;
      const double z = top ? base + half * 1.36 * f + w : base - base * std::pow(f, 0.25) + 0.5 * w * f;
      return dvec3(x, y, std::max(z, 0.0));
    };
  };
  TriangleMesh top = parametric_grid(resolution, resolution, sheet(true));
  TriangleMesh bottom = parametric_grid(resolution, resolution, sheet(false), true);
  const uint32_t offset = static_cast<uint32_t>(top.positions.size());
  for (size_t i = 0; i < bottom.positions.size(); ++i) {
    top.positions.push_back(bottom.positions[i]);
    top.uvs.push_back(bottom.uvs[i]);
  }
  for (auto t : bottom.triangles) top.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return top;
}

TriangleMesh floor_cloth_mesh(double size_x, double size_y, double fold_height, double flat_radius, int resolution) {
  return parametric_grid(resolution, resolution, [=](double s, double t) {
    const double x = (s - 0.5) * size_x, y = (t - 0.5) * size_y;
    const double r = std::hypot(x, y);
    const double e = std::clamp((r - flat_radius) / (0.6 * flat_radius), 0.0, 1.0);
    const double ramp = e * e * (3 - 2 * e);  // smoothstep: flat where the object stands
    // A few broad folds running across the cloth, as when it has been pushed together.
    const double folds = 0.55 * std::sin(1.7 * x + 0.5 * y + 0.3) + 0.3 * std::sin(2.9 * x - 1.1 * y + 1.9) +
                         0.15 * std::sin(4.3 * y + 0.7);
    return dvec3(x, y, 0.01 + fold_height * ramp * std::max(0.0, 0.5 + 0.5 * folds));
  });
}

TriangleMesh curtain_mesh(double width, double height, int folds, double fold_depth, int resolution) {
  const int nv = resolution, nu = std::max(2, resolution * 2);
  // UV u runs down the drop (the warp hangs vertically), v across.
  TriangleMesh m = parametric_grid(nu, nv, [=](double s, double t) {
    const double x = (t - 0.5) * width;
    const double z = height * (1.0 - s);
    const double depth = fold_depth * (0.6 + 0.4 * s);  // pleats open toward the hem
    const double y = depth * std::sin(2 * kPi * folds * t) + 0.15 * fold_depth * std::sin(5.3 * s + 3.0 * t);
    return dvec3(x, y, z);
  });
  return m;
}

TriangleMesh bezier_patch_mesh(const std::filesystem::path& file, int resolution) {
  std::ifstream in(file);
  if (!in) throw MeshError("cannot open Bézier patch file " + file.string());
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  for (char& c : s)
    if (c == ',') c = ' ';
  std::istringstream tokens(s);
  const std::string where = "Bézier patch file " + file.string();
  size_t patches = 0;
  if (!(tokens >> patches) || patches == 0 || patches > 10000) throw MeshError(where + ": bad patch count");
  std::vector<std::array<int, 16>> index(patches);
  for (auto& p : index)
    for (int& i : p)
      if (!(tokens >> i)) throw MeshError(where + ": truncated patch indices");
  size_t points = 0;
  if (!(tokens >> points) || points == 0 || points > 100000) throw MeshError(where + ": bad point count");
  std::vector<dvec3> cp(points);
  for (auto& p : cp)
    if (!(tokens >> p.x >> p.y >> p.z)) throw MeshError(where + ": truncated control points");
  for (const auto& p : index)
    for (int i : p)
      if (i < 1 || static_cast<size_t>(i) > points)
        throw MeshError(where + ": control point index " + std::to_string(i) + " out of 1.." + std::to_string(points));

  auto bernstein = [](double u, std::array<double, 4>& b) {
    const double v = 1 - u;
    b = {v * v * v, 3 * v * v * u, 3 * v * u * u, u * u * u};
  };
  TriangleMesh m;
  for (const auto& p : index) {
    TriangleMesh patch = parametric_grid(resolution, resolution, [&](double u, double v) {
      std::array<double, 4> bu, bv;
      bernstein(u, bu);
      bernstein(v, bv);
      dvec3 sum(0.0);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) sum += bu[i] * bv[j] * cp[p[i * 4 + j] - 1];
      return sum;
    }, true);  // Newell's patches are wound so that (u, v) gives an inward normal
    const uint32_t offset = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), patch.positions.begin(), patch.positions.end());
    for (auto t : patch.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  weld_vertices(m, 1e-6);
  return m;
}

void transform_mesh(TriangleMesh& mesh, double scale, double rotate_z_deg, const dvec3& translate) {
  const double a = rotate_z_deg * kPi / 180.0, c = std::cos(a), s = std::sin(a);
  auto rotate = [&](const dvec3& v) { return dvec3(c * v.x - s * v.y, s * v.x + c * v.y, v.z); };
  for (auto& p : mesh.positions) p = rotate(p * scale) + translate;
  for (auto& n : mesh.normals) n = rotate(n);
  for (auto& w : mesh.warps) w = rotate(w);
}

}  // namespace weft
