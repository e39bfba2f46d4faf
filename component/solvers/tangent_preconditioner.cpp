#include "solvers/tangent_preconditioner.hpp"

#include <vector>

#include "core/errors.hpp"

namespace peristep {

TangentPreconditioner::TangentPreconditioner(DynamicProblem& problem) : n_(problem.dofs()) {
  const std::vector<double> zero(n_, 0.0);
  A0_ = problem.model().tangent(zero.data());
  const std::vector<char>& fixed = problem.prescribed();
  A0_.prune([&fixed](Eigen::Index r, Eigen::Index c, double) { return !fixed[r] && !fixed[c]; });
  A0_ /= problem.density();
  const auto n = static_cast<Eigen::Index>(n_);
  Eigen::SparseMatrix<double> I(n, n);
  I.setIdentity();
  M_ = I - A0_;  // the pattern of I - gamma^2 A0 for every gamma
  ldlt_.analyzePattern(M_);
  rhs_.resize(n);
  zu_.resize(n);
}

void TangentPreconditioner::setup(double gamma) {
  if (gamma == gamma_) return;
  const auto n = static_cast<Eigen::Index>(n_);
  Eigen::SparseMatrix<double> I(n, n);
  I.setIdentity();
  M_ = I - (gamma * gamma) * A0_;
  ldlt_.factorize(M_);
  if (ldlt_.info() != Eigen::Success)
    throw SolverFailure("tangent preconditioner: factorization of I - gamma^2 A0 failed (gamma = " +
                        std::to_string(gamma) + ")");
  gamma_ = gamma;
  ++factorizations_;
}

void TangentPreconditioner::solve(const double* r, double* z, double gamma) {
  // The integrator calls setup() when gamma has drifted (CVODE: by more than 30 %); in between the
  // factorization of the last setup serves, as is usual for a preconditioner.
  if (gamma_ < 0) setup(gamma);
  const auto n = static_cast<Eigen::Index>(n_);
  const Eigen::Map<const Eigen::VectorXd> ru(r, n), rv(r + n, n);
  Eigen::Map<Eigen::VectorXd> zu(z, n), zv(z + n, n);
  rhs_ = ru + gamma * rv;
  zu_ = ldlt_.solve(rhs_);
  zu = zu_;
  zv = rv + gamma * (A0_ * zu_);
}

}  // namespace peristep
