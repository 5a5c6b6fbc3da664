#pragma once
// PCA compression of the per-vertex SDFs (seed 000 §4: "compressed by using PCA with 48 PCA
// terms"): d_v ≈ mean + Σ_k c_{v,k} · basis_k. The number of terms is the smallest that keeps
// the RMS reconstruction error (over all vertices and cells, radians) under a target.
#include <Eigen/Dense>
#include <vector>

namespace weft {

struct SdfPcaOptions {
  double target_rms_error = 0.01;  // radians (0.57°); cell side at 128² is π/128 ≈ 0.0245
  int max_terms = 64;
  // Above this many columns and rows the basis comes from randomised subspace iteration
  // (exact residuals for the basis it finds; see visibility_pca.cpp), below it from a full SVD.
  int exact_svd_limit = 1024;
};

struct SdfPca {
  Eigen::VectorXf mean;          // cells
  Eigen::MatrixXf basis;         // cells × terms, orthonormal columns
  Eigen::MatrixXf coefficients;  // terms × vertices
  // rms_error_by_terms[k] = RMS reconstruction error with k terms (k = 0 is the mean only),
  // for every k the decomposition computed; the chosen k is basis.cols().
  std::vector<double> rms_error_by_terms;
  double rms_error = 0;  // at the chosen number of terms
  double max_error = 0;  // worst |error| of any cell of any vertex at the chosen terms
  int terms() const { return int(basis.cols()); }
  // Reconstructed SDF of one vertex (cells).
  Eigen::VectorXf reconstruct(int vertex) const;
};

// `sdfs` is cells × vertices (one column per vertex, e.g. a 128×128 grid flattened row-major).
SdfPca fit_sdf_pca(const Eigen::MatrixXf& sdfs, const SdfPcaOptions& options = {});

}  // namespace weft
