#include "bake/visibility/visibility_sdf.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace weft {

namespace {

constexpr double kPi = std::numbers::pi;
// Stand-in for "no feature": large enough to lose every comparison, small enough that the
// parabola intersections of Felzenszwalb–Huttenlocher stay finite (no inf − inf).
constexpr double kNoFeature = 1e20;

// 1D squared distance transform of sampled function f (FH 2012, Algorithm 1): the lower
// envelope of the parabolas (q − p)² + f(p), then read off at every q.
void distance_transform_1d(const double* f, int n, double* out, std::vector<int>& v,
                           std::vector<double>& z) {
  v.resize(n);
  z.resize(n + 1);
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  for (int q = 1; q < n; ++q) {
    double s;
    for (;;) {
      const int p = v[k];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s <= z[k]) --k;  // z[0] = −∞ stops this at k = 0
      else break;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    out[q] = dq * dq + f[v[k]];
  }
}

}  // namespace

dvec3 direction_from_angles(const SurfaceFrame& frame, double theta, double phi) {
  return std::sin(theta) * frame.u +
         std::cos(theta) * (std::cos(phi) * frame.n + std::sin(phi) * frame.v);
}

VisibilityGrid sample_visibility(const SurfaceFrame& frame, const dvec3& origin, int resolution,
                                 const OcclusionQuery& occluded) {
  if (resolution < 2 || resolution > 8192)
    throw std::invalid_argument("visibility resolution must be in [2, 8192], got " +
                                std::to_string(resolution));
  const double h = kPi / resolution;
  VisibilityGrid grid{resolution, 2 * resolution, {}};
  grid.values.assign(size_t(grid.rows) * grid.cols, 0);
  for (int i = 0; i < grid.rows; ++i) {
    const double theta = cell_centre(-kPi / 2, h, i);
    for (int j = 0; j < grid.cols; ++j) {
      const double phi = cell_centre(-kPi, h, j);
      if (std::abs(phi) >= kPi / 2) continue;  // below the surface: occluded by itself
      const dvec3 dir = direction_from_angles(frame, theta, phi);
      grid.at(i, j) = occluded(origin, dir) ? 0 : 1;
    }
  }
  return grid;
}

std::vector<double> squared_distance_transform(const std::vector<uint8_t>& feature, int rows,
                                               int cols, bool periodic_cols) {
  if (rows <= 0 || cols <= 0 || feature.size() != size_t(rows) * cols)
    throw std::invalid_argument("distance transform: grid size does not match its data");
  std::vector<double> g(feature.size());
  std::vector<int> v;
  std::vector<double> z;
  // Pass 1: along θ (columns of the grid), never periodic (θ = ±π/2 are the poles).
  {
    std::vector<double> f(rows), out(rows);
    for (int j = 0; j < cols; ++j) {
      for (int i = 0; i < rows; ++i) f[i] = feature[size_t(i) * cols + j] ? 0.0 : kNoFeature;
      distance_transform_1d(f.data(), rows, out.data(), v, z);
      for (int i = 0; i < rows; ++i) g[size_t(i) * cols + j] = out[i];
    }
  }
  // Pass 2: along φ. A periodic row is tripled: the nearest image of any feature is within
  // half a period, so shifts by −1, 0, +1 periods are all the minimum can need.
  {
    const int copies = periodic_cols ? 3 : 1;
    const int n = copies * cols;
    std::vector<double> f(n), out(n);
    for (int i = 0; i < rows; ++i) {
      const double* row = &g[size_t(i) * cols];
      for (int c = 0; c < copies; ++c)
        for (int j = 0; j < cols; ++j) f[size_t(c) * cols + j] = row[j];
      distance_transform_1d(f.data(), n, out.data(), v, z);
      const int first = periodic_cols ? cols : 0;
      for (int j = 0; j < cols; ++j) g[size_t(i) * cols + j] = out[first + j];
    }
  }
  for (double& x : g)
    if (x >= kNoFeature / 2) x = std::numeric_limits<double>::infinity();
  return g;
}

DistanceGrid signed_distance(const VisibilityGrid& visibility, double h, bool periodic_cols,
                             bool boundary_offset) {
  if (!(h > 0)) throw std::invalid_argument("signed distance: cell size must be positive");
  const size_t n = visibility.values.size();
  std::vector<uint8_t> occluded(n), visible(n);
  for (size_t k = 0; k < n; ++k) {
    visible[k] = visibility.values[k] ? 1 : 0;
    occluded[k] = 1 - visible[k];
  }
  const std::vector<double> to_occluded =
      squared_distance_transform(occluded, visibility.rows, visibility.cols, periodic_cols);
  const std::vector<double> to_visible =
      squared_distance_transform(visible, visibility.rows, visibility.cols, periodic_cols);
  DistanceGrid d{visibility.rows, visibility.cols, std::vector<double>(n)};
  const double offset = boundary_offset ? 0.5 * h : 0.0;
  for (size_t k = 0; k < n; ++k) {
    const double sq = visible[k] ? to_occluded[k] : to_visible[k];
    if (std::isinf(sq)) {  // no boundary anywhere: as far from an edge as the domain allows
      d.values[k] = visible[k] ? kPi : -kPi;
      continue;
    }
    const double dist = std::sqrt(sq) * h - offset;
    d.values[k] = visible[k] ? dist : -dist;
  }
  return d;
}

SdfGradient sdf_gradient(const DistanceGrid& d, double h, bool periodic_cols) {
  SdfGradient g{{d.rows, d.cols, std::vector<double>(d.values.size())},
                {d.rows, d.cols, std::vector<double>(d.values.size())}};
  for (int i = 0; i < d.rows; ++i) {
    for (int j = 0; j < d.cols; ++j) {
      // θ: central inside, one-sided at the poles.
      const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, d.rows - 1);
      g.d_theta.at(i, j) = i1 > i0 ? (d.at(i1, j) - d.at(i0, j)) / ((i1 - i0) * h) : 0.0;
      int j0 = j - 1, j1 = j + 1;
      if (periodic_cols) {
        j0 = (j0 + d.cols) % d.cols;
        j1 = j1 % d.cols;
        g.d_phi.at(i, j) = d.cols > 1 ? (d.at(i, j1) - d.at(i, j0)) / (2 * h) : 0.0;
      } else {
        j0 = std::max(j0, 0);
        j1 = std::min(j1, d.cols - 1);
        g.d_phi.at(i, j) = j1 > j0 ? (d.at(i, j1) - d.at(i, j0)) / ((j1 - j0) * h) : 0.0;
      }
    }
  }
  return g;
}

VertexSdf vertex_sdf(const SurfaceFrame& frame, const dvec3& origin, int resolution,
                     int supersample, const OcclusionQuery& occluded) {
  if (supersample < 1 || supersample > 16)
    throw std::invalid_argument("SDF supersampling must be in [1, 16], got " +
                                std::to_string(supersample));
  if (resolution < 2 || resolution % 2)
    throw std::invalid_argument("SDF resolution must be even (the hemisphere is half the φ "
                                "circle), got " + std::to_string(resolution));
  const int fine = resolution * supersample;
  const double h_fine = kPi / fine;
  const VisibilityGrid vis = sample_visibility(frame, origin, fine, occluded);
  // Only the hemisphere is kept, and everything below it is occluded, so the full periodic
  // circle reduces to the hemisphere plus one occluded column on each side (the horizon): from a
  // hemisphere cell, any φ path across the seam is longer than the direct one (|Δφ| < π), and
  // the nearest occluded cell below the horizon is in the first column past it. Same values as
  // signed_distance(vis, h, true, true) cropped (tested), at a quarter of the cost.
  VisibilityGrid framed{fine, fine + 2, std::vector<uint8_t>(size_t(fine) * (fine + 2), 0)};
  for (int i = 0; i < fine; ++i)
    for (int j = 0; j < fine; ++j) framed.at(i, j + 1) = vis.at(i, fine / 2 + j);
  const DistanceGrid framed_d = signed_distance(framed, h_fine, /*periodic_cols=*/false,
                                                /*boundary_offset=*/true);
  DistanceGrid hemi{fine, fine, std::vector<double>(size_t(fine) * fine)};
  for (int i = 0; i < fine; ++i)
    for (int j = 0; j < fine; ++j) hemi.at(i, j) = framed_d.at(i, j + 1);
  VertexSdf out;
  out.h = kPi / resolution;
  out.d = {resolution, resolution, std::vector<double>(size_t(resolution) * resolution, 0.0)};
  // Box filter: each coarse cell is the mean of its s×s fine cells (same centre).
  const double w = 1.0 / (double(supersample) * supersample);
  for (int i = 0; i < hemi.rows; ++i)
    for (int j = 0; j < hemi.cols; ++j)
      out.d.at(i / supersample, j / supersample) += w * hemi.at(i, j);
  return out;
}

}  // namespace weft
