#pragma once
// Preconditioner for the Newton systems of an implicit integrator on y = (u, v):
//   M = I - gamma J,  J = [[0, I], [A, 0]],  A = d(acceleration)/du.
// With A replaced by A0, the rest-state tangent restricted to the free dofs, P z = r is solved exactly:
//   (I - gamma^2 A0) z_u = r_u + gamma r_v,   z_v = r_v + gamma A0 z_u.
// -A0 is symmetric positive semidefinite (with one density; with a density per point D, -S =
// -D^1/2 A0 D^-1/2 is), so I - gamma^2 A0 (I - gamma^2 S) is SPD: a sparse LDL^T, factorized in setup()
// (the pattern is analysed once) and reused by solve() for nearby gamma.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "solvers/dynamic_problem.hpp"

namespace peristep {

class TangentPreconditioner {
 public:
  explicit TangentPreconditioner(DynamicProblem& problem);

  void setup(double gamma);  // factorize I - gamma^2 A0 (no-op when gamma is unchanged)
  // r, z: 2n values each (u part then v part), n = problem dofs.
  void solve(const double* r, double* z, double gamma);
  long factorizations() const { return factorizations_; }

 private:
  std::size_t n_;
  // S (A0 itself with one density)
  const Eigen::SparseMatrix<double>& symmetric() const { return sqrtRho_.size() > 0 ? S_ : A0_; }

  Eigen::SparseMatrix<double> A0_, S_;  // S_ only with a density per point
  Eigen::VectorXd sqrtRho_;             // per dof, with a density per point; else empty
  Eigen::SparseMatrix<double> M_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  double gamma_ = -1;
  long factorizations_ = 0;
  Eigen::VectorXd rhs_, zu_;
};

}  // namespace peristep
