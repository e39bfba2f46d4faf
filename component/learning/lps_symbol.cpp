#include "learning/lps_symbol.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"

namespace peristep::learning {

namespace {
// Eigenvalues of a symmetric 2x2 matrix, ascending.
std::array<double, 2> eigenvalues(const Symbol& S) {
  const double mean = 0.5 * (S[0] + S[2]), d = std::hypot(0.5 * (S[0] - S[2]), S[1]);
  return {mean - d, mean + d};
}
}  // namespace

Symbol lpsSymbol(const LatticeStencil& st, const BernsteinKernel& kernel, double lambda, double mu, double kx,
                 double ky) {
  double m = 0.0, sx = 0.0, sy = 0.0, Txx = 0.0, Txy = 0.0, Tyy = 0.0;
  for (std::size_t s = 0; s < st.size(); ++s) {
    const double KW = kernel(st.r[s]) * st.W[s], r2 = st.r[s] * st.r[s];
    const double phase = kx * st.zx[s] + ky * st.zy[s];
    m += KW * r2;
    sx += KW * st.zx[s] * std::sin(phase);
    sy += KW * st.zy[s] * std::sin(phase);
    const double c = KW * (1.0 - std::cos(phase)) / r2;
    Txx += c * st.zx[s] * st.zx[s];
    Txy += c * st.zx[s] * st.zy[s];
    Tyy += c * st.zy[s] * st.zy[s];
  }
  const double a = (lambda - mu) * kC1 * kDim / (m * m), g = mu * kC2 / m;
  return {a * sx * sx + g * Txx, a * sx * sy + g * Txy, a * sy * sy + g * Tyy};
}

Solvability checkSolvability(const PeriodicLattice& lat, const LatticeStencil& st, const BernsteinKernel& kernel,
                             double lambda, double mu) {
  Solvability out;
  out.moduli = lambda + mu > 0 && mu > 0 && kernel.alpha < 3;
  out.minEigen = INFINITY;
  out.maxEigen = -INFINITY;
  const double tau = 2.0 * std::numbers::pi;
  for (std::size_t j = 0; j < lat.ny; ++j)
    for (std::size_t i = 0; i < lat.nx; ++i) {
      if (i == 0 && j == 0) continue;
      const double kx = tau * static_cast<double>(i) / (static_cast<double>(lat.nx) * lat.hx);
      const double ky = tau * static_cast<double>(j) / (static_cast<double>(lat.ny) * lat.hy);
      const auto e = eigenvalues(lpsSymbol(st, kernel, lambda, mu, kx, ky));
      out.minEigen = std::min(out.minEigen, e[0]);
      out.maxEigen = std::max(out.maxEigen, e[1]);
    }
  return out;
}

StaticSample cosineLoadSample(const PeriodicLattice& lat, const LatticeStencil& st, const BernsteinKernel& kernel,
                              double lambda, double mu, double kx, double ky, int component, double amplitude) {
  require(kx != 0.0 || ky != 0.0, "cosine load: k = 0 is a net force, a periodic sheet has no equilibrium");
  // cos(kx x) cos(ky y) = (cos(kx x + ky y) + cos(kx x - ky y))/2; S(k) = S(-k).
  std::array<double, 2> v[2];
  for (int sgn = 0; sgn < 2; ++sgn) {
    const Symbol S = lpsSymbol(st, kernel, lambda, mu, kx, sgn == 0 ? ky : -ky);
    const double det = S[0] * S[2] - S[1] * S[1];
    require(std::abs(det) > 1e-300, "cosine load: the operator is singular at this wave vector");
    const double e[2] = {component == 0 ? amplitude : 0.0, component == 1 ? amplitude : 0.0};
    v[sgn] = {0.5 * (S[2] * e[0] - S[1] * e[1]) / det, 0.5 * (-S[1] * e[0] + S[0] * e[1]) / det};
  }
  StaticSample out;
  out.u.resize(2 * lat.size());
  out.b.resize(2 * lat.size());
  for (std::size_t p = 0; p < lat.size(); ++p) {
    const double x = static_cast<double>(p % lat.nx) * lat.hx, y = static_cast<double>(p / lat.nx) * lat.hy;
    const double cp = std::cos(kx * x + ky * y), cm = std::cos(kx * x - ky * y);
    for (int c = 0; c < 2; ++c) {
      out.u[2 * p + c] = v[0][c] * cp + v[1][c] * cm;
      out.b[2 * p + c] = c == component ? amplitude * std::cos(kx * x) * std::cos(ky * y) : 0.0;
    }
  }
  return out;
}

}  // namespace peristep::learning
