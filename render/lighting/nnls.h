#pragma once
// Non-negative least squares on the normal equations: the amplitudes of a fixed set of SG lobes.
#include <Eigen/Dense>

namespace weft {

// Minimises ½ xᵀ A x − bᵀ x subject to x ≥ 0, for a symmetric positive (semi)definite A — i.e.
// min ‖Mx − y‖² with A = MᵀM, b = Mᵀy. Lawson & Hanson's active-set method: grow the set of free
// (positive) variables by the one with the most positive gradient b − Ax, solve the free block
// exactly, and when that solution leaves the feasible set step back to its boundary and free
// nothing new. Exact (to round-off) in a finite number of steps; K ≤ ~100 here, so dense LDLᵀ.
Eigen::VectorXd solve_nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace weft
