#include "gauss_rules.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>

namespace peristep::sampling {
namespace detail {
namespace {

using MatrixR = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

// Enforces the symmetry of the weight on the computed nodes: x_{n-1-i} = -x_i, middle node exactly 0.
void symmetrize(std::vector<Real>& nodes) {
  const std::size_t n = nodes.size();
  for (std::size_t i = 0; i < n / 2; ++i) {
    const Real x = (nodes[n - 1 - i] - nodes[i]) / 2;
    nodes[i] = -x;
    nodes[n - 1 - i] = x;
  }
  if (n % 2 == 1) nodes[n / 2] = 0;
}

}  // namespace

RealRule gaussRuleReal(Law law, int points) {
  if (points < 1) throw std::invalid_argument("gaussRule: need at least 1 point, got " + std::to_string(points));
  const int n = points;
  // Golub-Welsch: the nodes are the eigenvalues of the symmetric tridiagonal Jacobi matrix.
  MatrixR jacobi = MatrixR::Zero(n, n);
  for (int k = 1; k < n; ++k) jacobi(k, k - 1) = jacobi(k - 1, k) = recurrenceCoefficient(law, k);
  Eigen::SelfAdjointEigenSolver<MatrixR> eigen(jacobi, Eigen::EigenvaluesOnly);
  if (eigen.info() != Eigen::Success) throw std::runtime_error("gaussRule: Jacobi eigenproblem did not converge");

  RealRule rule;
  rule.nodes.resize(n);
  for (int i = 0; i < n; ++i) {
    // Newton on p_n polishes the eigenvalues to the last bit of long double.
    Real x = eigen.eigenvalues()(i);
    for (int it = 0; it < 3; ++it) {
      const PolynomialValue p = orthonormalPolynomial(law, n, x);
      if (p.derivative == 0) break;
      x -= p.value / p.derivative;
    }
    rule.nodes[i] = x;
  }
  symmetrize(rule.nodes);
  rule.weights.resize(n);
  Real sum = 0;
  for (int i = 0; i < n; ++i) sum += rule.weights[i] = christoffelWeight(law, n, rule.nodes[i]);
  for (Real& w : rule.weights) w /= sum;
  return rule;
}

Rule1D toDouble(const RealRule& rule) {
  const std::size_t n = rule.nodes.size();
  Rule1D out;
  out.nodes.resize(n);
  out.weights.resize(n);
  for (std::size_t i = n / 2; i < n; ++i) {
    const std::size_t mirror = n - 1 - i;
    out.nodes[i] = static_cast<double>(rule.nodes[i]);
    out.nodes[mirror] = -out.nodes[i];
    out.weights[i] = out.weights[mirror] = static_cast<double>((rule.weights[i] + rule.weights[mirror]) / 2);
  }
  return out;
}

}  // namespace detail

Rule1D gaussRule(Law law, int points) { return detail::toDouble(detail::gaussRuleReal(law, points)); }

}  // namespace peristep::sampling
