#include "learning/damaged_lps_operator.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "learning/lps_residual.hpp"

namespace peristep::learning {

namespace {

// Eigenvalues of the shape tensor below this fraction of the largest count as zero in its pseudo-inverse
// (003:(32)): a nearly collinear remainder of bonds otherwise gives a dilatation of O(1/eigenvalue).
constexpr double kPseudoInverseTolerance = 1e-2;

// Symmetric 2x2 (pseudo-)inverse M of the shape tensor A (003:(32); 003 Sec. 3.2: isolated points), both
// stored as (xx, xy, yy).
void shapeInverse(const double A[3], double M[3]) {
  const double tr = A[0] + A[2], det = A[0] * A[2] - A[1] * A[1];
  const double disc = std::sqrt(std::max(0.0, 0.25 * tr * tr - det));
  const double l1 = 0.5 * tr + disc, l2 = 0.5 * tr - disc;
  double v1[2] = {A[1], l1 - A[0]};
  if (std::hypot(v1[0], v1[1]) < 1e-14 * (std::abs(tr) + 1e-300)) v1[0] = 1, v1[1] = 0;
  const double nv = std::hypot(v1[0], v1[1]);
  v1[0] /= nv, v1[1] /= nv;
  const double tol = kPseudoInverseTolerance * std::max(std::abs(l1), 1e-300);
  const double i1 = std::abs(l1) > tol ? 1 / l1 : 0, i2 = std::abs(l2) > tol ? 1 / l2 : 0;
  M[0] = i1 * v1[0] * v1[0] + i2 * v1[1] * v1[1];
  M[1] = (i1 - i2) * v1[0] * v1[1];
  M[2] = i1 * v1[1] * v1[1] + i2 * v1[0] * v1[0];
}

std::vector<std::ptrdiff_t> gridNeighbours(const CoarseGrid& g, const LatticeStencil& st) {
  std::vector<std::ptrdiff_t> nb(g.size() * st.size(), -1);
  for (std::size_t p = 0; p < g.size(); ++p) {
    const auto i = static_cast<std::ptrdiff_t>(p % g.nx), j = static_cast<std::ptrdiff_t>(p / g.nx);
    for (std::size_t s = 0; s < st.size(); ++s) {
      const std::ptrdiff_t ii = i + st.di[s], jj = j + st.dj[s];
      if (ii >= 0 && jj >= 0 && ii < static_cast<std::ptrdiff_t>(g.nx) && jj < static_cast<std::ptrdiff_t>(g.ny))
        nb[p * st.size() + s] = ii + static_cast<std::ptrdiff_t>(g.nx) * jj;
    }
  }
  return nb;
}

}  // namespace

DamagedLpsOperator::DamagedLpsOperator(CoarseGrid grid, LatticeStencil stencil, const BernsteinKernel& kernel,
                                       double lambda, double mu, double eta)
    : grid_(grid), stencil_(std::move(stencil)), lambda_(lambda), mu_(mu), eta_(eta) {
  require(!grid_.periodic && grid_.hx == stencil_.hx && grid_.hy == stencil_.hy,
          "damaged LPS operator: the lattice and the stencil differ");
  for (std::size_t s = 0; s < stencil_.size(); ++s) {
    KW_.push_back(kernel(stencil_.r[s]) * stencil_.W[s]);
    m_ += KW_.back() * stencil_.r[s] * stencil_.r[s];
  }
  neighbour_ = gridNeighbours(grid_, stencil_);
}

std::vector<double> DamagedLpsOperator::slit(double ax, double ay, double bx, double by) const {
  const std::size_t S = stencil_.size();
  std::vector<double> smax(neighbour_.size(), -INFINITY);
  const auto side = [](double px, double py, double qx, double qy, double rx, double ry) {
    return (qx - px) * (ry - py) - (qy - py) * (rx - px);
  };
  for (std::size_t p = 0; p < grid_.size(); ++p)
    for (std::size_t s = 0; s < S; ++s) {
      const std::ptrdiff_t q = neighbour_[p * S + s];
      if (q < 0) continue;
      const double px = grid_.x(p), py = grid_.y(p), qx = grid_.x(static_cast<std::size_t>(q)),
                   qy = grid_.y(static_cast<std::size_t>(q));
      // Proper intersection of the bond p-q with the slit a-b.
      if (side(ax, ay, bx, by, px, py) * side(ax, ay, bx, by, qx, qy) < 0 &&
          side(px, py, qx, qy, ax, ay) * side(px, py, qx, qy, bx, by) < 0)
        smax[p * S + s] = INFINITY;
    }
  return smax;
}

void DamagedLpsOperator::updateMaxStretch(const std::vector<double>& u, std::vector<double>& smax) const {
  const std::size_t S = stencil_.size();
  smax.resize(neighbour_.size(), -INFINITY);
  for (std::size_t p = 0; p < grid_.size(); ++p)
    for (std::size_t s = 0; s < S; ++s) {
      const std::ptrdiff_t q = neighbour_[p * S + s];
      if (q < 0) continue;
      const double dx = stencil_.zx[s] + u[2 * q] - u[2 * p], dy = stencil_.zy[s] + u[2 * q + 1] - u[2 * p + 1];
      smax[p * S + s] = std::max(smax[p * S + s], std::hypot(dx, dy) / stencil_.r[s] - 1.0);  // 003:(23)
    }
}

std::vector<double> DamagedLpsOperator::bondStates(const std::vector<double>& smax, double s0) const {
  std::vector<double> gam(smax.size());  // 003:(28)
  for (std::size_t k = 0; k < smax.size(); ++k) gam[k] = 0.5 * (1.0 - std::tanh((smax[k] - s0) / eta_));
  return gam;
}

std::vector<double> DamagedLpsOperator::damage(const std::vector<double>& smax, double s0) const {
  const std::size_t S = stencil_.size();
  const std::vector<double> gam = bondStates(smax, s0);
  std::vector<double> phi(grid_.size(), 0.0);
  for (std::size_t p = 0; p < grid_.size(); ++p) {
    double sum = 0, count = 0;
    for (std::size_t s = 0; s < S; ++s)
      if (neighbour_[p * S + s] >= 0) sum += gam[p * S + s], count += 1;
    phi[p] = count > 0 ? 1.0 - sum / count : 0.0;  // 003:(46)
  }
  return phi;
}

std::vector<double> DamagedLpsOperator::apply(const std::vector<double>& u, const std::vector<double>& smax,
                                              double s0) const {
  const CoarseGrid& g = grid_;
  const std::size_t S = stencil_.size(), n = g.size();
  const std::vector<double> gam = bondStates(smax, s0);
  const auto gamma = [&](std::size_t p, std::size_t s) { return gam[p * S + s]; };
  // 003:(31)-(33): corrected dilatation and normal at every point.
  std::vector<double> theta(n, 0.0), nx(n, 0.0), ny(n, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    double A[3] = {0, 0, 0}, mv[2] = {0, 0};
    for (std::size_t s = 0; s < S; ++s) {
      if (neighbour_[p * S + s] < 0) continue;
      const double kg = kDim / m_ * KW_[s] * gamma(p, s);
      A[0] += kg * stencil_.zx[s] * stencil_.zx[s];
      A[1] += kg * stencil_.zx[s] * stencil_.zy[s];
      A[2] += kg * stencil_.zy[s] * stencil_.zy[s];
      mv[0] += stencil_.zx[s] * stencil_.W[s] * gamma(p, s);
      mv[1] += stencil_.zy[s] * stencil_.W[s] * gamma(p, s);
    }
    // The uncorrected theta of 003:(15) is the corrected one with the identity for the tensor's inverse.
    double M[3] = {1, 0, 1};
    if (corrected_) shapeInverse(A, M);
    double t = 0.0;
    for (std::size_t s = 0; s < S; ++s) {
      const std::ptrdiff_t q = neighbour_[p * S + s];
      if (q < 0) continue;
      const double dux = u[2 * q] - u[2 * p], duy = u[2 * q + 1] - u[2 * p + 1];
      t += KW_[s] * gamma(p, s) * (stencil_.zx[s] * (M[0] * dux + M[1] * duy) + stencil_.zy[s] * (M[1] * dux + M[2] * duy));
    }
    theta[p] = kDim / m_ * t;
    const double mn = std::hypot(mv[0], mv[1]);
    if (mn > 1e-12 * stencil_.delta) nx[p] = -mv[0] / mn, ny[p] = -mv[1] / mn;
  }
  std::vector<double> L(2 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    const double px = -ny[p], py = nx[p];  // tangent
    double Lx = 0, Ly = 0, free = 0;
    for (std::size_t s = 0; s < S; ++s) {
      const double zx = stencil_.zx[s], zy = stencil_.zy[s], r2 = stencil_.r[s] * stencil_.r[s];
      const std::ptrdiff_t q = neighbour_[p * S + s];
      // Bonds to points outside the grid count as broken (free surface), like cracked ones.
      const double gm = q < 0 ? 0.0 : gamma(p, s), KW = KW_[s];
      if (q >= 0) {
        const double dux = u[2 * q] - u[2 * p], duy = u[2 * q + 1] - u[2 * p + 1];
        const double dil = -kC1 / m_ * (lambda_ - mu_) * KW * gm * (theta[p] + theta[q]);
        const double dev = -kC2 / m_ * mu_ * KW * gm * (zx * dux + zy * duy) / r2;
        Lx += (dil + dev) * zx;
        Ly += (dil + dev) * zy;
      }
      const double kb = KW * (1.0 - gm);
      if (kb == 0.0 || !freeSurface_) continue;
      const double zn = zx * nx[p] + zy * ny[p], zp = zx * px + zy * py;
      Lx += -2.0 * kC1 * theta[p] / m_ * (lambda_ - mu_) * kb * zx;
      Ly += -2.0 * kC1 * theta[p] / m_ * (lambda_ - mu_) * kb * zy;
      free += kb * (-(lambda_ + 2.0 * mu_) * zn * zp * zp + lambda_ * zn * zn * zn) / r2;
    }
    L[2 * p] = Lx + kC2 * theta[p] / (2.0 * m_) * free * nx[p];
    L[2 * p + 1] = Ly + kC2 * theta[p] / (2.0 * m_) * free * ny[p];
  }
  return L;
}

}  // namespace peristep::learning
