#include "patterson_extension.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gauss_rules.hpp"

namespace peristep::sampling::detail {
namespace {

using MatrixR = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
using VectorR = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

// The roots from the comrade matrix are only as good as the coefficients beta (exactness defects of
// 3e-17 at 31 Gauss-Patterson and 2.6e-16 at 35 Genz-Keister nodes), so they start Newton's method
// on the conditions themselves (defects 2e-18 and 1.5e-16 after it):
//   F_k(y) = E[q(x) pi(x) p_k(x)] = 0,  q(x) = prod_j (x^2 - y_j^2),
// for the k of the parity that makes the integrand even (the others vanish by symmetry). Both
// products are evaluated as products, at the nodes of a Gauss rule exact for the integrand.
void polishRoots(Law law, const std::vector<Real>& nodes, std::vector<Real>& y) {
  const int h = static_cast<int>(y.size()), m = static_cast<int>(nodes.size());
  const RealRule gauss = gaussRuleReal(law, 2 * h + m / 2 + 1);  // degree 4h + m - 1 needed
  for (int iteration = 0; iteration < 8; ++iteration) {
    MatrixR jacobian = MatrixR::Zero(h, h);
    VectorR f = VectorR::Zero(h), scale = VectorR::Zero(h);
    for (std::size_t g = 0; g < gauss.nodes.size(); ++g) {
      const Real z = gauss.nodes[g];
      Real pi = 1, q = 1;
      for (const Real x : nodes) pi *= z - x;
      for (const Real yj : y) q *= z * z - yj * yj;
      const std::vector<Real> basis = orthonormalPolynomials(law, 2 * h, z);
      for (int e = 0; e < h; ++e) {
        const Real common = gauss.weights[g] * pi * basis[2 * e + m % 2];
        f(e) += common * q;
        scale(e) += std::abs(common * q);
        for (int j = 0; j < h; ++j) {
          Real qj = -2 * y[j];  // d/dy_j (z^2 - y_j^2) times the other factors
          for (int i = 0; i < h; ++i)
            if (i != j) qj *= z * z - y[i] * y[i];
          jacobian(e, j) += common * qj;
        }
      }
    }
    for (int e = 0; e < h; ++e) {
      f(e) /= scale(e);
      jacobian.row(e) /= scale(e);
    }
    const VectorR step = jacobian.fullPivLu().solve(f);
    Real largest = 0;
    for (int j = 0; j < h; ++j) {
      y[j] -= step(j);
      largest = std::max(largest, std::abs(step(j)) / (1 + std::abs(y[j])));
    }
    if (largest < 1e-18L) return;
  }
  // Not converged to the last bit: the caller's exactness check decides whether the rule is usable.
}

}  // namespace

std::vector<Real> pattersonNodes(Law law, const std::vector<Real>& nodes, int count) {
  if (count < 2 || count % 2 != 0) throw std::invalid_argument("pattersonNodes: count must be even and >= 2");
  const int p = count;
  // Orthogonality conditions sum_{b<=p} beta_b E[p_b pi p_k] = 0, k < p, with beta_p = 1. The
  // expectations by a Gauss rule exact for them, pi evaluated as a product; rows scaled to unit maximum.
  const RealRule gauss = gaussRuleReal(law, p + static_cast<int>(nodes.size()) / 2 + 1);
  MatrixR a = MatrixR::Zero(p, p + 1);
  for (std::size_t g = 0; g < gauss.nodes.size(); ++g) {
    const Real z = gauss.nodes[g];
    Real pi = gauss.weights[g];
    for (const Real x : nodes) pi *= z - x;
    const std::vector<Real> basis = orthonormalPolynomials(law, p, z);
    for (int k = 0; k < p; ++k)
      for (int b = 0; b <= p; ++b) a(k, b) += pi * basis[k] * basis[b];
  }
  for (int k = 0; k < p; ++k) a.row(k) /= a.row(k).cwiseAbs().maxCoeff();
  const VectorR rhs = -a.col(p);
  const Eigen::FullPivLU<MatrixR> lu(a.leftCols(p));
  if (!lu.isInvertible()) throw std::runtime_error("pattersonNodes: singular orthogonality conditions");
  const VectorR solution = lu.solve(rhs);
  std::vector<Real> beta(solution.data(), solution.data() + p);
  beta.push_back(1);

  // Roots of q: eigenvalues of the comrade matrix J_p - s_p e_{p-1} beta^T (beta_p = 1): at a root
  // x p_{p-1} = s_{p-1} p_{p-2} + s_p p_p with p_p = -sum_{b<p} beta_b p_b.
  MatrixR comrade = MatrixR::Zero(p, p);
  for (int k = 1; k < p; ++k) comrade(k, k - 1) = comrade(k - 1, k) = recurrenceCoefficient(law, k);
  for (int b = 0; b < p; ++b) comrade(p - 1, b) -= recurrenceCoefficient(law, p) * beta[b];
  const Eigen::EigenSolver<MatrixR> eigen(comrade, false);
  if (eigen.info() != Eigen::Success) throw std::runtime_error("pattersonNodes: comrade eigenproblem did not converge");

  std::vector<Real> added;
  for (int i = 0; i < p; ++i) {
    const std::complex<Real> root = eigen.eigenvalues()(i);
    if (std::abs(root.imag()) > 1e-8L * (1 + std::abs(root.real())))
      throw std::runtime_error("pattersonNodes: no real extension by " + std::to_string(p) + " nodes");
    added.push_back(root.real());
  }
  std::sort(added.begin(), added.end());
  // q is even (the conditions are invariant under x -> -x): its roots come in pairs +-y.
  std::vector<Real> half(added.begin() + p / 2, added.end());
  for (int i = 0; i < p / 2; ++i) half[i] = (half[i] - added[p / 2 - 1 - i]) / 2;
  polishRoots(law, nodes, half);
  for (int i = 0; i < p / 2; ++i) {
    added[p / 2 + i] = half[i];
    added[p / 2 - 1 - i] = -half[i];
  }
  for (int i = 0; i < p; ++i) {
    if (law == Law::Uniform && std::abs(added[i]) >= 1)
      throw std::runtime_error("pattersonNodes: extension node outside [-1, 1]");
    if (i > 0 && added[i] - added[i - 1] < 1e-10L) throw std::runtime_error("pattersonNodes: repeated root");
    for (const Real x : nodes)
      if (std::abs(added[i] - x) < 1e-10L) throw std::runtime_error("pattersonNodes: root on an existing node");
  }
  return added;
}

std::vector<Real> interpolatoryWeights(Law law, const std::vector<Real>& nodes) {
  // Moment conditions sum_i w_i p_k(x_i) = E[p_k] = [k == 0], k < n, in the orthonormal basis: far
  // better conditioned than Lagrange polynomials or monomials for these node sets.
  const int n = static_cast<int>(nodes.size());
  MatrixR v(n, n);
  for (int i = 0; i < n; ++i) {
    const std::vector<Real> basis = orthonormalPolynomials(law, n - 1, nodes[i]);
    for (int k = 0; k < n; ++k) v(k, i) = basis[k];
  }
  const VectorR w = v.fullPivLu().solve(VectorR::Unit(n, 0));
  return std::vector<Real>(w.data(), w.data() + n);
}

Real exactnessDefect(Law law, const std::vector<Real>& nodes, const std::vector<Real>& weights, int degree) {
  std::vector<Real> sums(degree + 1, 0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::vector<Real> basis = orthonormalPolynomials(law, degree, nodes[i]);
    for (int k = 0; k <= degree; ++k) sums[k] += weights[i] * basis[k];
  }
  Real defect = std::abs(sums[0] - 1);
  for (int k = 1; k <= degree; ++k) defect = std::max(defect, std::abs(sums[k]));
  return defect;
}

}  // namespace peristep::sampling::detail
