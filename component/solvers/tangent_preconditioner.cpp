#include "solvers/tangent_preconditioner.hpp"

#include <cmath>
#include <vector>

#include "core/errors.hpp"

namespace peristep {

TangentPreconditioner::TangentPreconditioner(DynamicProblem& problem) : n_(problem.dofs()) {
  const std::vector<double> zero(n_, 0.0);
  A0_ = problem.model().tangent(zero.data());
  const std::vector<char>& fixed = problem.prescribed();
  A0_.prune([&fixed](Eigen::Index r, Eigen::Index c, double) { return !fixed[r] && !fixed[c]; });
  const std::vector<double>& rho = problem.pointDensity();
  if (rho.empty()) {
    A0_ /= problem.density();
  } else {
    // A0 = D^-1 K with D the density per dof is not symmetric, but D^1/2 A0 D^-1/2 = D^-1/2 K D^-1/2 is:
    // (I - gamma^2 A0) z = b  <=>  (I - gamma^2 S) (D^1/2 z) = D^1/2 b.
    Eigen::VectorXd s(static_cast<Eigen::Index>(n_)), inv(static_cast<Eigen::Index>(n_));
    for (std::size_t d = 0; d < n_; ++d) {
      s[static_cast<Eigen::Index>(d)] = std::sqrt(rho[d / 2]);
      inv[static_cast<Eigen::Index>(d)] = 1.0 / rho[d / 2];
    }
    const Eigen::VectorXd isq = s.cwiseInverse();
    S_ = isq.asDiagonal() * A0_ * isq.asDiagonal();
    A0_ = inv.asDiagonal() * A0_;
    sqrtRho_ = s;
  }
  const auto n = static_cast<Eigen::Index>(n_);
  Eigen::SparseMatrix<double> I(n, n);
  I.setIdentity();
  M_ = I - symmetric();  // the pattern of I - gamma^2 S for every gamma
  ldlt_.analyzePattern(M_);
  rhs_.resize(n);
  zu_.resize(n);
}

void TangentPreconditioner::setup(double gamma) {
  if (gamma == gamma_) return;
  const auto n = static_cast<Eigen::Index>(n_);
  Eigen::SparseMatrix<double> I(n, n);
  I.setIdentity();
  M_ = I - (gamma * gamma) * symmetric();
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
  if (sqrtRho_.size() > 0) {
    rhs_ = sqrtRho_.cwiseProduct(rhs_);
    zu_ = ldlt_.solve(rhs_).cwiseQuotient(sqrtRho_);
  } else {
    zu_ = ldlt_.solve(rhs_);
  }
  zu = zu_;
  zv = rv + gamma * (A0_ * zu_);
}

}  // namespace peristep
