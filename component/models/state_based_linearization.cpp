// Linearization of the state-based force 001:(14)-(15): Jacobian-vector products for the Krylov
// solver of the implicit integrator and the assembled tangent for its preconditioner and for the
// stability limit of the explicit one.
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

#include "models/state_based_model.hpp"

namespace peristep {

void StateBasedModel::forceDerivative(const double* u, const double* du, double* df) {
  const StateBasedBonds& b = bonds_;
  const double beta = material_.f.beta;
  const auto n = static_cast<std::ptrdiff_t>(points());
  if (hydrostatic_) {
    updateHydrostatic(u);
    hydrostaticStrain(du, dtheta_.data());  // theta is linear in u
#pragma omp parallel for schedule(static) if (parallel_)
    for (std::ptrdiff_t i = 0; i < n; ++i) dkg1_[i] = b.kappa[i] * material_.g.curvature(theta_[i]) * dtheta_[i];
  }
  const double* dkg1 = dkg1_.data();
  const bool hydro = hydrostatic_;
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double ux = u[2 * i], uy = u[2 * i + 1], dux = du[2 * i], duy = du[2 * i + 1];
    double fx = 0, fy = 0;
    for (std::size_t k = b.offset[i]; k < b.offset[i + 1]; ++k) {
      const std::size_t j = b.neighbour[k];
      const double r = (u[2 * j] - ux) * b.qx(k) + (u[2 * j + 1] - uy) * b.qy(k);
      const double dr = (du[2 * j] - dux) * b.qx(k) + (du[2 * j + 1] - duy) * b.qy(k);
      // f''(r)/(2 c beta) = (1 - 2 beta r^2) exp(-beta r^2)
      const double t = b.w[k] * (1.0 - 2.0 * beta * r * r) * std::exp(-beta * r * r) * dr;
      fx += t * b.qx(k);
      fy += t * b.qy(k);
    }
    fx *= tensileScale_;
    fy *= tensileScale_;
    if (hydro) {
      double hx = 0, hy = 0;
      for (std::size_t k = b.offset[i]; k < b.offset[i + 1]; ++k) {
        const double s = b.ws[k] * (dkg1[i] + dkg1[b.neighbour[k]]);
        hx += s * b.qx(k);
        hy += s * b.qy(k);
      }
      fx += hydroScale_ * hx;
      fy += hydroScale_ * hy;
    }
    df[2 * i] = b.omega[i] * fx;
    df[2 * i + 1] = b.omega[i] * fy;
  }
}

Eigen::SparseMatrix<double> StateBasedModel::tangent(const double* u) {
  using Triplet = Eigen::Triplet<double>;
  const StateBasedBonds& b = bonds_;
  const double beta = material_.f.beta;
  const auto n = static_cast<Eigen::Index>(points());
  std::vector<Triplet> t;
  t.reserve(8 * b.bonds() + 4 * points());
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    const double ux = u[2 * i], uy = u[2 * i + 1];
    double dxx = 0, dxy = 0, dyy = 0;
    for (std::size_t k = b.offset[iu]; k < b.offset[iu + 1]; ++k) {
      const auto j = static_cast<Eigen::Index>(b.neighbour[k]);
      const double r = (u[2 * j] - ux) * b.qx(k) + (u[2 * j + 1] - uy) * b.qy(k);
      const double a = tensileScale_ * b.omega[iu] * b.w[k] * (1.0 - 2.0 * beta * r * r) * std::exp(-beta * r * r);
      const double axx = a * b.qx(k) * b.qx(k), axy = a * b.qx(k) * b.qy(k), ayy = a * b.qy(k) * b.qy(k);
      t.emplace_back(2 * i, 2 * j, axx);
      t.emplace_back(2 * i, 2 * j + 1, axy);
      t.emplace_back(2 * i + 1, 2 * j, axy);
      t.emplace_back(2 * i + 1, 2 * j + 1, ayy);
      dxx -= axx;
      dxy -= axy;
      dyy -= ayy;
    }
    t.emplace_back(2 * i, 2 * i, dxx);
    t.emplace_back(2 * i, 2 * i + 1, dxy);
    t.emplace_back(2 * i + 1, 2 * i, dxy);
    t.emplace_back(2 * i + 1, 2 * i + 1, dyy);
  }
  Eigen::SparseMatrix<double> K(2 * n, 2 * n);
  K.setFromTriplets(t.begin(), t.end());
  if (!hydrostatic_) return K;

  // Hydrostatic part: L_D = H kappa g'(theta) with theta = G u, so dL_D/du = H diag(kappa g''(theta)) G.
  hydrostaticStrain(u, theta_.data());
  std::vector<Triplet> tg, th;
  tg.reserve(4 * b.bonds());
  th.reserve(4 * b.bonds());
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    for (std::size_t k = b.offset[iu]; k < b.offset[iu + 1]; ++k) {
      const auto j = static_cast<Eigen::Index>(b.neighbour[k]);
      const double gx = thetaScale_ * b.ws[k] * b.qx(k), gy = thetaScale_ * b.ws[k] * b.qy(k);
      tg.emplace_back(i, 2 * j, gx);
      tg.emplace_back(i, 2 * j + 1, gy);
      tg.emplace_back(i, 2 * i, -gx);
      tg.emplace_back(i, 2 * i + 1, -gy);
      const double hx = hydroScale_ * b.omega[iu] * b.ws[k] * b.qx(k), hy = hydroScale_ * b.omega[iu] * b.ws[k] * b.qy(k);
      th.emplace_back(2 * i, i, hx);
      th.emplace_back(2 * i + 1, i, hy);
      th.emplace_back(2 * i, j, hx);
      th.emplace_back(2 * i + 1, j, hy);
    }
  }
  Eigen::SparseMatrix<double> G(n, 2 * n), H(2 * n, n);
  G.setFromTriplets(tg.begin(), tg.end());
  H.setFromTriplets(th.begin(), th.end());
  Eigen::VectorXd d(n);
  for (Eigen::Index i = 0; i < n; ++i) d[i] = b.kappa[static_cast<std::size_t>(i)] * material_.g.curvature(theta_[i]);
  Eigen::SparseMatrix<double> HD = H * d.asDiagonal();
  Eigen::SparseMatrix<double> KD = HD * G;
  return K + KD;
}

}  // namespace peristep
