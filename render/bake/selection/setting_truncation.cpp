#include "bake/selection/setting_truncation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace weft {

namespace {

// Table `c` cut to rank r (row-major factors keep their first r columns).
CompressedTable cut(const CompressedTable& c, int r, int xi_nodes, int wo_nodes) {
  CompressedTable out;
  out.rank = r;
  out.norm = c.norm;
  out.u.resize(size_t(xi_nodes) * r);
  out.v.resize(size_t(wo_nodes) * r);
  for (int i = 0; i < xi_nodes; ++i)
    for (int k = 0; k < r; ++k) out.u[size_t(i) * r + k] = c.u[size_t(i) * c.rank + k];
  for (int i = 0; i < wo_nodes; ++i)
    for (int k = 0; k < r; ++k) out.v[size_t(i) * r + k] = c.v[size_t(i) * c.rank + k];
  return out;
}

}  // namespace

WeightingTables truncate_tables(const WeightingTables& full, double svd_error, int level_stride) {
  const int levels = full.level_count();
  if (level_stride < 1 || levels < 1 || (levels - 1) % level_stride != 0)
    throw std::invalid_argument("truncate_tables: level stride " + std::to_string(level_stride) + " does not divide " +
                                std::to_string(levels - 1) + " level intervals");
  WeightingTables out;
  out.tangent_samples = full.tangent_samples;
  out.tilts = full.tilts;
  out.xi_grid = full.xi_grid;
  out.wo_grid = full.wo_grid;
  out.sample_table = full.sample_table;
  for (int l = 0; l < levels; l += level_stride) out.lambdas.push_back(full.lambdas[l]);
  const int xi_nodes = full.xi_grid.size(), wo_nodes = full.wo_grid.size();
  for (int d = 0; d < full.distinct_count(); ++d)
    for (int l = 0; l < levels; l += level_stride) {
      const CompressedTable& c = full.tables[size_t(d) * levels + l];
      if (c.norm <= 0.0 || c.rank == 0) {
        out.tables.push_back(cut(c, 0, xi_nodes, wo_nodes));
        out.tables.back().error = c.error;
        continue;
      }
      // V has orthonormal columns and U carries the singular values: s_k = ‖U[:, k]‖, and the
      // error of the first r columns is sqrt(‖T‖² − Σ_{k<r} s_k²)/‖T‖.
      const double norm2 = c.norm * c.norm;
      double kept = 0.0;
      int r = 0;
      double err = 1.0;
      while (r < c.rank) {
        err = std::sqrt(std::max(0.0, norm2 - kept) / norm2);
        if (err <= svd_error) break;
        double s2 = 0.0;
        for (int i = 0; i < xi_nodes; ++i) s2 += double(c.u[size_t(i) * c.rank + r]) * c.u[size_t(i) * c.rank + r];
        kept += s2;
        ++r;
      }
      if (r == c.rank) err = c.error;  // all kept: the bake's own measure
      out.tables.push_back(cut(c, r, xi_nodes, wo_nodes));
      out.tables.back().error = err;
    }
  return out;
}

ObjectVisibility truncate_visibility(const ObjectVisibility& full, double rms_error) {
  const size_t cells = full.mean.size(), vertices = full.vertex_count();
  const int terms = full.terms;
  if (terms == 0 || vertices == 0) return full;
  // The basis is orthonormal: dropping terms k ≥ r adds Σ_v Σ_{k≥r} c_{v,k}² to the squared
  // error summed over vertices and cells.
  std::vector<double> energy(terms, 0.0);
  for (size_t v = 0; v < vertices; ++v)
    for (int k = 0; k < terms; ++k) energy[k] += double(full.coefficients[v * terms + k]) * full.coefficients[v * terms + k];
  const double n = double(cells) * double(vertices);
  double tail = 0.0;
  int r = terms;
  double err = full.rms_error;
  while (r > 0) {
    const double e = std::sqrt(full.rms_error * full.rms_error + (tail + energy[r - 1]) / n);
    if (e > rms_error) break;
    tail += energy[r - 1];
    --r;
    err = e;
  }
  if (r == terms) return full;
  ObjectVisibility out;
  out.resolution = full.resolution;
  out.terms = r;
  out.mean = full.mean;
  out.basis.assign(full.basis.begin(), full.basis.begin() + size_t(r) * cells);
  out.coefficients.resize(vertices * r);
  for (size_t v = 0; v < vertices; ++v)
    for (int k = 0; k < r; ++k) out.coefficients[v * r + k] = full.coefficients[v * terms + k];
  out.rms_error = err;
  // The worst cell moves by at most the dropped terms' contribution there.
  double worst = 0.0;
  std::vector<double> dropped(cells);
  for (size_t v = 0; v < vertices; ++v) {
    std::fill(dropped.begin(), dropped.end(), 0.0);
    for (int k = r; k < terms; ++k) {
      const double c = full.coefficients[v * terms + k];
      const float* b = full.basis.data() + size_t(k) * cells;
      for (size_t i = 0; i < cells; ++i) dropped[i] += c * b[i];
    }
    for (size_t i = 0; i < cells; ++i) worst = std::max(worst, std::abs(dropped[i]));
  }
  out.max_error = full.max_error + worst;
  return out;
}

}  // namespace weft
