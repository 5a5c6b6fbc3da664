// Cutting cheaper settings from a richer bake: a table cut to a looser SVD target equals its
// best rank-r approximation (error checked against the table rebuilt from the full factors),
// every other level is the same table as a bake at those levels, and a PCA cut keeps the
// error it reports (checked by reconstruction).
#include <gtest/gtest.h>

#include <cmath>

#include "bake/selection/setting_truncation.h"
#include "bake/visibility/visibility_pca.h"
#include "bake/tables/weighting_bake.h"
#include "core/fabric.h"

using namespace weft;

namespace {
WeightingTables small_bake(int levels, double svd_error) {
  BakeSettings b;
  b.tangent_samples = {2, 2};
  b.xi_resolution = b.wo_resolution = b.wi_resolution = 10;
  b.lambda_levels = levels;
  b.svd_error = svd_error;
  return bake_weighting_tables(load_fabric_preset("linen_plain", WEFT_SOURCE_ASSETS "/fabrics"), b);
}
// ‖A − B‖_F / ‖A‖_F of two compressed tables of the same grids, rebuilt in full.
double difference(const CompressedTable& a, const CompressedTable& b, int rows, int cols) {
  double d2 = 0.0, n2 = 0.0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      double x = 0.0, y = 0.0;
      for (int k = 0; k < a.rank; ++k) x += double(a.u[i * a.rank + k]) * a.v[j * a.rank + k];
      for (int k = 0; k < b.rank; ++k) y += double(b.u[i * b.rank + k]) * b.v[j * b.rank + k];
      d2 += (x - y) * (x - y), n2 += x * x;
    }
  return std::sqrt(d2 / n2);
}
}  // namespace

TEST(TableTruncation, LooserSvdTargetCutsRanksAndReportsTheError) {
  const WeightingTables full = small_bake(5, 1e-4);
  const WeightingTables cut = truncate_tables(full, 0.05, 1);
  ASSERT_EQ(cut.tables.size(), full.tables.size());
  const int rows = full.xi_grid.size(), cols = full.wo_grid.size();
  bool some_cut = false;
  for (size_t i = 0; i < full.tables.size(); ++i) {
    const CompressedTable &f = full.tables[i], &c = cut.tables[i];
    if (f.norm <= 0.0) continue;
    EXPECT_LE(c.rank, f.rank);
    some_cut = some_cut || c.rank < f.rank;
    EXPECT_LE(c.error, 0.05 + 1e-9);
    // Against the nearly exact full table: the reported error, up to the full one's 1e-4.
    EXPECT_NEAR(difference(f, c, rows, cols), c.error, 2e-3) << "table " << i;
  }
  EXPECT_TRUE(some_cut);
  EXPECT_EQ(truncate_tables(full, 1.0, 1).tables[0].rank, 0);
}

TEST(TableTruncation, EveryOtherLevelIsTheBakeAtThoseLevels) {
  const WeightingTables full = small_bake(5, 1e-4);
  const WeightingTables direct = small_bake(3, 1e-4);
  const WeightingTables cut = truncate_tables(full, 1e-4, 2);
  ASSERT_EQ(cut.lambdas.size(), direct.lambdas.size());
  for (size_t l = 0; l < cut.lambdas.size(); ++l) EXPECT_NEAR(cut.lambdas[l], direct.lambdas[l], 1e-9 * direct.lambdas[l]);
  const int rows = full.xi_grid.size(), cols = full.wo_grid.size();
  for (size_t i = 0; i < cut.tables.size(); ++i)
    if (direct.tables[i].norm > 0.0) { EXPECT_LT(difference(direct.tables[i], cut.tables[i], rows, cols), 1e-3); }
  EXPECT_THROW(truncate_tables(full, 0.01, 3), std::invalid_argument);
}

TEST(VisibilityTruncation, FewerTermsKeepTheReportedRmsError) {
  // Smooth random-ish SDFs: 64 cells, 200 vertices, a few strong directions plus noise.
  const int cells = 64, vertices = 200;
  Eigen::MatrixXf sdfs(cells, vertices);
  for (int v = 0; v < vertices; ++v)
    for (int c = 0; c < cells; ++c)
      sdfs(c, v) = float(std::sin(0.1 * c * (1 + v % 7)) + 0.3 * std::cos(0.37 * c + v) + 0.01 * std::sin(13.0 * c * v));
  SdfPcaOptions po;
  po.target_rms_error = 1e-4;
  po.max_terms = 40;
  const SdfPca pca = fit_sdf_pca(sdfs, po);
  ObjectVisibility full;
  full.resolution = 8;
  full.terms = pca.terms();
  full.mean.assign(pca.mean.data(), pca.mean.data() + cells);
  for (int k = 0; k < pca.terms(); ++k)
    for (int c = 0; c < cells; ++c) full.basis.push_back(pca.basis(c, k));
  for (int v = 0; v < vertices; ++v)
    for (int k = 0; k < pca.terms(); ++k) full.coefficients.push_back(pca.coefficients(k, v));
  full.rms_error = pca.rms_error, full.max_error = pca.max_error;

  const ObjectVisibility cut = truncate_visibility(full, 0.05);
  EXPECT_LT(cut.terms, full.terms);
  EXPECT_LE(cut.rms_error, 0.05);
  double se = 0.0, worst = 0.0;
  for (int v = 0; v < vertices; ++v)
    for (int c = 0; c < cells; ++c) {
      double d = cut.mean[c];
      for (int k = 0; k < cut.terms; ++k) d += double(cut.coefficients[v * cut.terms + k]) * cut.basis[k * cells + c];
      se += (d - sdfs(c, v)) * (d - sdfs(c, v));
      worst = std::max(worst, std::abs(d - sdfs(c, v)));
    }
  EXPECT_NEAR(std::sqrt(se / (cells * vertices)), cut.rms_error, 1e-3);
  EXPECT_LE(worst, cut.max_error + 1e-5);
  EXPECT_EQ(truncate_visibility(full, 1e-9).terms, full.terms);
}
