#include "runtime/weighting_tables.h"

#include <algorithm>
#include <cmath>

namespace weft {

double WeightingTables::node_value(int t, int level, int xi_node, int wo_node) const {
  const CompressedTable& c = table(t, level);
  double sum = 0.0;
  for (int r = 0; r < c.rank; ++r)
    sum += double(c.u[size_t(xi_node) * c.rank + r]) * c.v[size_t(wo_node) * c.rank + r];
  return sum;
}

void WeightingTables::level_weights(double lambda, int& l0, int& l1, double& f) const {
  // Level weights: linear in log λ.
  l0 = 0, l1 = 0;
  f = 0.0;
  if (lambdas.empty()) return;
  const double ll = std::log(std::clamp(lambda, lambdas.front(), lambdas.back()));
  if (lambdas.size() > 1) {
    l0 = 0;
    while (l0 + 2 < level_count() && std::log(lambdas[l0 + 1]) < ll) ++l0;
    l1 = l0 + 1;
    f = std::clamp((ll - std::log(lambdas[l0])) / (std::log(lambdas[l1]) - std::log(lambdas[l0])), 0.0, 1.0);
  }
}

double WeightingTables::value(int t, double lambda, const glm::dvec3& xi, const glm::dvec3& wo) const {
  if (lambdas.empty()) return 0.0;
  int l0 = 0, l1 = 0;
  double f = 0.0;
  level_weights(lambda, l0, l1, f);
  const BilinearTap a = xi_grid.tap(xi), b = wo_grid.tap(wo);
  double total = 0.0;
  for (int k = 0; k < 2; ++k) {
    const int level = k == 0 ? l0 : l1;
    const double wl = k == 0 ? 1.0 - f : f;
    if (wl == 0.0) continue;
    const CompressedTable& c = table(t, level);
    // Σ_r (Σ_a w_a U[a,r]) (Σ_b w_b V[b,r]): interpolate the factors, then one dot product.
    double sum = 0.0;
    for (int r = 0; r < c.rank; ++r) {
      double ur = 0.0, vr = 0.0;
      for (int q = 0; q < 4; ++q) {
        ur += a.weight[q] * c.u[size_t(a.index[q]) * c.rank + r];
        vr += b.weight[q] * c.v[size_t(b.index[q]) * c.rank + r];
      }
      sum += ur * vr;
    }
    total += wl * sum;
  }
  return total;
}

std::size_t WeightingTables::bytes() const {
  std::size_t b = 0;
  for (const CompressedTable& c : tables) b += (c.u.size() + c.v.size()) * sizeof(float);
  return b;
}

}  // namespace weft

#include <map>

namespace weft {

TableSummary summarize(const WeightingTables& tables) {
  TableSummary s;
  if (tables.tables.empty()) return s;
  std::map<int, int> hist;
  s.min_rank = tables.tables.front().rank;
  for (const CompressedTable& c : tables.tables) {
    s.min_rank = std::min(s.min_rank, c.rank);
    s.max_rank = std::max(s.max_rank, c.rank);
    s.mean_rank += c.rank;
    s.mean_error += c.error;
    s.max_error = std::max(s.max_error, c.error);
    ++hist[c.rank];
  }
  s.mean_rank /= tables.tables.size();
  s.mean_error /= tables.tables.size();
  s.rank_histogram.assign(hist.begin(), hist.end());
  return s;
}

}  // namespace weft
