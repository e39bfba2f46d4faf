#include "solvers/stability_limit.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "core/errors.hpp"

namespace peristep {
namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

StabilityEstimate estimateStabilityLimit(DynamicProblem& problem, int maxIterations) {
  const std::size_t n = problem.dofs();
  const std::vector<char>& fixed = problem.prescribed();
  std::vector<double> zero(n, 0.0), v(n), w(n), prev(n, 0.0);
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> normal;
  for (std::size_t i = 0; i < n; ++i) v[i] = fixed[i] ? 0.0 : normal(rng);
  double norm = std::sqrt(dot(v, v));
  require(norm > 0, "stability limit: every dof is prescribed, nothing moves");
  for (double& x : v) x /= norm;

  // Lanczos on the symmetric operator -A (uniform point volumes make dL/du symmetric).
  std::vector<double> alpha, beta;
  double betaPrev = 0;
  for (int m = 0; m < maxIterations; ++m) {
    problem.accelerationDerivative(zero.data(), v.data(), w.data());
    for (std::size_t i = 0; i < n; ++i) w[i] = -w[i];
    const double a = dot(v, w);
    for (std::size_t i = 0; i < n; ++i) w[i] -= a * v[i] + betaPrev * prev[i];
    const double b = std::sqrt(dot(w, w));
    alpha.push_back(a);
    beta.push_back(b);
    if (!(b > 1e-12 * std::abs(a))) break;  // invariant subspace: the Ritz values are exact
    prev.swap(v);
    for (std::size_t i = 0; i < n; ++i) v[i] = w[i] / b;
    betaPrev = b;
  }
  // Ritz values from the (scaled) tridiagonal matrix, dense: k <= maxIterations is small.
  const auto k = static_cast<Eigen::Index>(alpha.size());
  double scale = 0;
  for (const double a : alpha) scale = std::max(scale, std::abs(a));
  if (!(scale > 0) || !std::isfinite(scale))
    throw SolverFailure("stability limit: the rest-state stiffness is zero or not finite");
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(k, k);
  for (Eigen::Index i = 0; i < k; ++i) {
    T(i, i) = alpha[static_cast<std::size_t>(i)] / scale;
    if (i + 1 < k) T(i, i + 1) = T(i + 1, i) = beta[static_cast<std::size_t>(i)] / scale;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(T);
  if (eig.info() != Eigen::Success) throw SolverFailure("stability limit: Lanczos Ritz values did not converge");
  const double theta = scale * eig.eigenvalues()[k - 1];
  // |lambda - theta| <= beta_k |s_k| for the Ritz pair (theta, s): add it to err on the safe side.
  const double residual = beta.back() * std::abs(eig.eigenvectors()(k - 1, k - 1));
  const double lambda = theta + residual;
  if (!(lambda > 0) || !std::isfinite(lambda))
    throw SolverFailure("stability limit: the rest-state stiffness has no positive eigenvalue (lambda = " +
                        std::to_string(lambda) + ")");
  StabilityEstimate s;
  s.omegaMax = std::sqrt(lambda);
  s.criticalStep = 2.0 / s.omegaMax;
  s.iterations = static_cast<int>(k);
  return s;
}

}  // namespace peristep
