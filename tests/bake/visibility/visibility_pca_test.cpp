// PCA compression of per-vertex SDFs: the error it reports is the error a reader gets back.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bake/visibility/visibility_pca.h"
#include "bake/visibility/visibility_sdf.h"

using namespace weft;

namespace {

// SDFs of vertices under random half-space occluders (a wall at a random azimuth and
// elevation): smooth families like a real scene's, computed through the real pipeline.
Eigen::MatrixXf random_scene_sdfs(int vertices, int resolution, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> azimuth(-3.14159, 3.14159), elevation(0.0, 1.2);
  Eigen::MatrixXf out(resolution * resolution, vertices);
  for (int v = 0; v < vertices; ++v) {
    const double az = azimuth(rng), el = elevation(rng);
    const dvec3 toward(std::cos(az), std::sin(az), 0);
    // Occluded below elevation `el` towards `toward`: ω·toward > 0 and tan(elev) < tan(el)·cos.
    auto occluded = [&](const dvec3&, const dvec3& w) {
      return std::tan(el) * glm::dot(w, toward) > w.z;
    };
    const VertexSdf sdf = vertex_sdf(SurfaceFrame{}, dvec3(0), resolution, 1, occluded);
    for (int k = 0; k < resolution * resolution; ++k) out(k, v) = float(sdf.d.values[k]);
  }
  return out;
}

double measured_rms(const SdfPca& pca, const Eigen::MatrixXf& sdfs) {
  double sum = 0;
  for (int v = 0; v < sdfs.cols(); ++v)
    sum += (pca.reconstruct(v) - sdfs.col(v)).cast<double>().squaredNorm();
  return std::sqrt(sum / double(sdfs.size()));
}

}  // namespace

TEST(SdfPca, ReportedErrorIsTheReconstructionErrorAndMeetsTheTarget) {
  const Eigen::MatrixXf sdfs = random_scene_sdfs(60, 32, 3);
  for (double target : {0.05, 0.02, 0.01}) {
    SdfPcaOptions opt;
    opt.target_rms_error = target;
    const SdfPca pca = fit_sdf_pca(sdfs, opt);
    EXPECT_LE(pca.rms_error, target);
    EXPECT_NEAR(pca.rms_error, measured_rms(pca, sdfs), 1e-6);
    // The curve predicts the measured error, and one term fewer would miss the target.
    EXPECT_NEAR(pca.rms_error_by_terms[pca.terms()], pca.rms_error, 1e-4);
    if (pca.terms() > 0) {
      EXPECT_GT(pca.rms_error_by_terms[pca.terms() - 1], target);
    }
    double worst = 0;
    for (int v = 0; v < sdfs.cols(); ++v)
      worst = std::max(worst, double((pca.reconstruct(v) - sdfs.col(v)).cwiseAbs().maxCoeff()));
    EXPECT_NEAR(pca.max_error, worst, 1e-5);
  }
}

TEST(SdfPca, ErrorFallsWithTermsAndRandomisedBasisMatchesExactOne) {
  const Eigen::MatrixXf sdfs = random_scene_sdfs(80, 32, 11);
  SdfPcaOptions exact;
  exact.target_rms_error = 0.005;
  SdfPcaOptions randomised = exact;
  randomised.exact_svd_limit = 8;  // force subspace iteration
  const SdfPca a = fit_sdf_pca(sdfs, exact), b = fit_sdf_pca(sdfs, randomised);
  for (size_t k = 1; k < a.rms_error_by_terms.size(); ++k)
    EXPECT_LE(a.rms_error_by_terms[k], a.rms_error_by_terms[k - 1] + 1e-7);
  EXPECT_NEAR(b.rms_error, measured_rms(b, sdfs), 1e-6);
  EXPECT_LE(b.rms_error, exact.target_rms_error);
  EXPECT_LE(std::abs(b.terms() - a.terms()), 2);
}

TEST(SdfPca, RejectsEmptyOrNonFiniteInput) {
  EXPECT_THROW(fit_sdf_pca(Eigen::MatrixXf()), std::invalid_argument);
  Eigen::MatrixXf bad = Eigen::MatrixXf::Zero(4, 3);
  bad(1, 1) = std::nanf("");
  EXPECT_THROW(fit_sdf_pca(bad), std::invalid_argument);
}
