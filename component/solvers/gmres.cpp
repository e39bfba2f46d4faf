#include "solvers/gmres.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace peristep {
namespace {

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double a : v) s += a * a;
  return std::sqrt(s);
}

}  // namespace

GmresResult gmres(const CsrMatrix& A, LinearSolver& M, std::span<const double> b, std::span<double> x, double tol,
                  int maxIterations, int restart) {
  return gmres([&](std::span<const double> in, std::span<double> out) { A.multiply(in, out); },
               [&](std::span<const double> in, std::span<double> out) { M.precondition(in, out); }, b, x, tol,
               maxIterations, restart);
}

GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, std::span<const double> b,
                  std::span<double> x, double tol, int maxIterations, int restart) {
  const std::size_t n = b.size();
  const auto m = static_cast<std::size_t>(restart);
  GmresResult result;
  const double bnorm = std::sqrt([&] {
    double s = 0;
    for (double a : b) s += a * a;
    return s;
  }());
  if (bnorm == 0) {
    std::fill(x.begin(), x.end(), 0.0);
    result.converged = true;
    return result;
  }
  std::vector<std::vector<double>> V(m + 1, std::vector<double>(n)), Z(m, std::vector<double>(n));
  std::vector<std::vector<double>> H(m + 1, std::vector<double>(m, 0.0));
  std::vector<double> cs(m), sn(m), g(m + 1), w(n), r(n);

  while (result.iterations < maxIterations) {
    apply(x, r);
    for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
    const double beta = norm(r);
    result.relativeResidual = beta / bnorm;
    if (result.relativeResidual <= tol) {
      result.converged = true;
      return result;
    }
    for (std::size_t i = 0; i < n; ++i) V[0][i] = r[i] / beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    std::size_t j = 0;
    for (; j < m && result.iterations < maxIterations; ++j) {
      ++result.iterations;
      precondition(V[j], Z[j]);  // right preconditioning: z_j = M^{-1} v_j
      apply(Z[j], w);
      for (std::size_t i = 0; i <= j; ++i) {  // modified Gram-Schmidt
        double h = 0;
        for (std::size_t k = 0; k < n; ++k) h += w[k] * V[i][k];
        H[i][j] = h;
        for (std::size_t k = 0; k < n; ++k) w[k] -= h * V[i][k];
      }
      H[j + 1][j] = norm(w);
      if (H[j + 1][j] > 0)
        for (std::size_t k = 0; k < n; ++k) V[j + 1][k] = w[k] / H[j + 1][j];
      for (std::size_t i = 0; i < j; ++i) {  // apply the earlier Givens rotations
        const double t = cs[i] * H[i][j] + sn[i] * H[i + 1][j];
        H[i + 1][j] = -sn[i] * H[i][j] + cs[i] * H[i + 1][j];
        H[i][j] = t;
      }
      const double d = std::hypot(H[j][j], H[j + 1][j]);
      cs[j] = d > 0 ? H[j][j] / d : 1.0;
      sn[j] = d > 0 ? H[j + 1][j] / d : 0.0;
      H[j][j] = d;
      H[j + 1][j] = 0;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      if (std::abs(g[j + 1]) / bnorm <= tol) {
        ++j;
        break;
      }
    }
    // x += Z y with H y = g (upper triangular, size j)
    std::vector<double> y(j);
    for (std::size_t i = j; i-- > 0;) {
      double s = g[i];
      for (std::size_t k = i + 1; k < j; ++k) s -= H[i][k] * y[k];
      y[i] = s / H[i][i];
    }
    for (std::size_t i = 0; i < j; ++i)
      for (std::size_t k = 0; k < n; ++k) x[k] += y[i] * Z[i][k];
  }
  apply(x, r);
  for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
  result.relativeResidual = norm(r) / bnorm;
  result.converged = result.relativeResidual <= tol;
  return result;
}

}  // namespace peristep
