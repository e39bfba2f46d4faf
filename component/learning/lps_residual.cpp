#include "learning/lps_residual.hpp"

#include "core/errors.hpp"
#include "core/parallel_errors.hpp"

namespace peristep::learning {

std::vector<double> applyLearnedLps(const PeriodicLattice& lat, const LatticeStencil& st, const BernsteinKernel& kernel,
                                    double lambda, double mu, const std::vector<double>& u) {
  const std::size_t n = lat.size(), S = st.size();
  std::vector<double> KW(S);
  double m = 0.0;  // m_i = sum_j K_ij |z|^2 W_ji, 003 below (18)
  for (std::size_t s = 0; s < S; ++s) {
    KW[s] = kernel(st.r[s]) * st.W[s];
    m += KW[s] * st.r[s] * st.r[s];
  }
  std::vector<double> theta(n, 0.0), L(2 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p) {  // 003:(18)
    double t = 0.0;
    for (std::size_t s = 0; s < S; ++s) {
      const std::size_t q = lat.neighbour(p, st.di[s], st.dj[s]);
      t += KW[s] * (st.zx[s] * (u[2 * q] - u[2 * p]) + st.zy[s] * (u[2 * q + 1] - u[2 * p + 1]));
    }
    theta[p] = kDim / m * t;
  }
  for (std::size_t p = 0; p < n; ++p) {  // 003:(17)
    double Lx = 0.0, Ly = 0.0;
    for (std::size_t s = 0; s < S; ++s) {
      const std::size_t q = lat.neighbour(p, st.di[s], st.dj[s]);
      const double dil = -kC1 / m * (lambda - mu) * KW[s] * (theta[p] + theta[q]);
      const double zdu = st.zx[s] * (u[2 * q] - u[2 * p]) + st.zy[s] * (u[2 * q + 1] - u[2 * p + 1]);
      const double dev = -kC2 / m * mu * KW[s] * zdu / (st.r[s] * st.r[s]);
      Lx += (dil + dev) * st.zx[s];
      Ly += (dil + dev) * st.zy[s];
    }
    L[2 * p] = Lx;
    L[2 * p + 1] = Ly;
  }
  return L;
}

StaticResidual::StaticResidual(PeriodicLattice lattice, LatticeStencil stencil, int order,
                               std::vector<StaticSample> samples, std::vector<double> weight)
    : lattice_(lattice), stencil_(std::move(stencil)), order_(order), samples_(std::move(samples)),
      weight_(std::move(weight)) {
  require(order >= 0, "learned kernel: the Bernstein order P must be >= 0");
  require(weight_.size() == samples_.size(), "learning residual: one weight per sample");
  for (std::size_t m = 0; m < samples_.size(); ++m) {
    require(samples_[m].u.size() == 2 * lattice_.size() && samples_[m].b.size() == 2 * lattice_.size(),
            "learning residual: a sample's u or b does not match the lattice");
    for (const double b : samples_[m].b) rhs_.push_back(weight_[m] * b);
  }
  for (std::size_t p = 0; p < lattice_.size(); ++p)
    for (std::size_t s = 0; s < stencil_.size(); ++s)
      neighbour_.push_back(static_cast<std::uint32_t>(lattice_.neighbour(p, stencil_.di[s], stencil_.dj[s])));
}

StaticResidual::Sums StaticResidual::build(double alpha) const {
  const std::size_t P1 = static_cast<std::size_t>(order_) + 1, S = stencil_.size(), n = lattice_.size();
  BernsteinKernel basis{stencil_.delta, alpha, std::vector<double>(P1, 0.0)};
  std::vector<double> phi(S * P1);  // phi_k(r_s) W_s
  Sums out{alpha, std::vector<double>(P1, 0.0), std::vector<double>(rhs_.size() * P1, 0.0),
           std::vector<double>(rhs_.size() * P1 * P1, 0.0)};
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t k = 0; k < P1; ++k) {
      phi[s * P1 + k] = basis.basis(static_cast<int>(k), stencil_.r[s]) * stencil_.W[s];
      out.mk[k] += phi[s * P1 + k] * stencil_.r[s] * stencil_.r[s];
    }
  // Bonds in pairs (z, -z): same r and W, so the u_p and t_p terms cancel and each pair needs one pass.
  std::vector<std::size_t> half;
  for (std::size_t s = 0; s < S; ++s)
    if (stencil_.dj[s] > 0 || (stencil_.dj[s] == 0 && stencil_.di[s] > 0)) half.push_back(s);
  // Samples fill disjoint rows: one per thread. The scratch allocation must not throw out of the region.
  ParallelErrors errors;
#pragma omp parallel
  errors.capture([&] {
    std::vector<double> t(n * P1);  // t_pk = sum_s phi_k z.(u_q - u_p): theta = (d/m) sum_k D_k t_pk
    std::vector<double> gx(P1), gy(P1), ax(P1 * P1), ay(P1 * P1), dt(P1);
#pragma omp for schedule(dynamic)
    for (std::size_t m = 0; m < samples_.size(); ++m) {
      const std::vector<double>& u = samples_[m].u;
      const std::size_t row0 = 2 * n * m;
      const double w = weight_[m];
      for (std::size_t p = 0; p < n; ++p) {
        std::fill(gx.begin(), gx.end(), 0.0), std::fill(gy.begin(), gy.end(), 0.0);
        double* tp = &t[p * P1];
        std::fill(tp, tp + P1, 0.0);
        for (const std::size_t s : half) {
          const std::size_t q = neighbour_[p * S + s], o = neighbour_[p * S + stencil_.opposite[s]];
          const double zx = stencil_.zx[s], zy = stencil_.zy[s], r2 = stencil_.r[s] * stencil_.r[s];
          // z.(u_q - u_p) and -z.(u_o - u_p): sum and difference of the pair
          const double tsum = zx * (u[2 * q] - u[2 * o]) + zy * (u[2 * q + 1] - u[2 * o + 1]);
          const double gsum = (zx * (u[2 * q] + u[2 * o] - 2 * u[2 * p]) +
                               zy * (u[2 * q + 1] + u[2 * o + 1] - 2 * u[2 * p + 1])) / r2;
          for (std::size_t k = 0; k < P1; ++k) {
            tp[k] += phi[s * P1 + k] * tsum;
            gx[k] += phi[s * P1 + k] * gsum * zx;
            gy[k] += phi[s * P1 + k] * gsum * zy;
          }
        }
        for (std::size_t k = 0; k < P1; ++k) {
          out.g[(row0 + 2 * p) * P1 + k] = w * gx[k];
          out.g[(row0 + 2 * p + 1) * P1 + k] = w * gy[k];
        }
      }
      // a_pkl = sum_s phi_k z (t_pl + t_ql): the dilatation term of 003:(17) is -(C1 d/m^2) sum_kl D_k D_l a_pkl.
      for (std::size_t p = 0; p < n; ++p) {
        std::fill(ax.begin(), ax.end(), 0.0), std::fill(ay.begin(), ay.end(), 0.0);
        for (const std::size_t s : half) {
          const std::size_t q = neighbour_[p * S + s], o = neighbour_[p * S + stencil_.opposite[s]];
          for (std::size_t l = 0; l < P1; ++l) dt[l] = t[q * P1 + l] - t[o * P1 + l];
          for (std::size_t k = 0; k < P1; ++k) {
            const double fx = phi[s * P1 + k] * stencil_.zx[s], fy = phi[s * P1 + k] * stencil_.zy[s];
            for (std::size_t l = 0; l < P1; ++l) {
              ax[k * P1 + l] += fx * dt[l];
              ay[k * P1 + l] += fy * dt[l];
            }
          }
        }
        for (std::size_t kl = 0; kl < P1 * P1; ++kl) {
          out.a[(row0 + 2 * p) * P1 * P1 + kl] = w * ax[kl];
          out.a[(row0 + 2 * p + 1) * P1 * P1 + kl] = w * ay[kl];
        }
      }
    }
  });
  errors.rethrow();
  return out;
}

const StaticResidual::Sums& StaticResidual::sums(double alpha) {
  for (const Sums& c : cache_)
    if (c.alpha == alpha) return c;
  if (cache_.size() == 3) cache_.erase(cache_.begin());
  cache_.push_back(build(alpha));
  return cache_.back();
}

void StaticResidual::columns(double alpha, const std::vector<double>& D, std::vector<double>& lambdaColumn,
                             std::vector<double>& muColumn) {
  const std::size_t P1 = static_cast<std::size_t>(order_) + 1;
  require(D.size() == P1, "learning residual: D needs P+1 coefficients");
  const Sums& sm = sums(alpha);
  double m = 0.0;
  for (std::size_t k = 0; k < P1; ++k) m += D[k] * sm.mk[k];
  std::vector<double> DD(P1 * P1);
  for (std::size_t k = 0; k < P1; ++k)
    for (std::size_t l = 0; l < P1; ++l) DD[k * P1 + l] = D[k] * D[l];
  const double cA = -kC1 * kDim / (m * m), cG = -kC2 / m;
  lambdaColumn.resize(rows());
  muColumn.resize(rows());
  for (std::size_t r = 0; r < rows(); ++r) {
    double A = 0.0, G = 0.0;
    const double* a = &sm.a[r * P1 * P1];
    for (std::size_t kl = 0; kl < P1 * P1; ++kl) A += DD[kl] * a[kl];
    for (std::size_t k = 0; k < P1; ++k) G += D[k] * sm.g[r * P1 + k];
    A *= cA;
    G *= cG;
    // L = (lambda - mu) A + mu G = lambda A + mu (G - A)
    lambdaColumn[r] = A;
    muColumn[r] = G - A;
  }
}

}  // namespace peristep::learning
