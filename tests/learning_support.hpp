#pragma once
// Synthetic data for the learning tests: a known sign-changing kernel and the loads of 003:(43).
#include <cmath>
#include <numbers>
#include <vector>

#include "learning/bernstein_kernel.hpp"
#include "learning/lps_symbol.hpp"

namespace peristep::learning::testing {

struct Truth {
  BernsteinKernel kernel;
  double lambda, mu;
};

// P = 3, alpha = 0.5, D of both signs (xi = (0.6, 0.9, -0.8, 0.3)), graphene-like moduli (lambda < 0).
inline Truth syntheticTruth(double delta) {
  Truth t{BernsteinKernel{delta, 0.5, {0.6, 0.9, -0.8, 0.3}}, -0.2, 0.7};
  for (int k = 0; k <= 3; ++k) t.kernel.D[static_cast<std::size_t>(k)] /= t.kernel.weightedVolumeCoefficient(k);
  return t;
}

// 003:(43): b = e_c cos(k1 x) cos(k2 y), k1, k2 in {0, 1, .., 5} 2 pi / L, both components, k != 0:
// 70 samples on a periodic lattice of side L.
inline std::vector<StaticSample> cosineSamples(const PeriodicLattice& lat, const LatticeStencil& st, const Truth& t,
                                               int kmax = 5) {
  std::vector<StaticSample> out;
  const double Lx = static_cast<double>(lat.nx) * lat.hx, Ly = static_cast<double>(lat.ny) * lat.hy;
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i <= kmax; ++i)
      for (int j = 0; j <= kmax; ++j) {
        if (i == 0 && j == 0) continue;
        out.push_back(cosineLoadSample(lat, st, t.kernel, t.lambda, t.mu, 2 * std::numbers::pi * i / Lx,
                                       2 * std::numbers::pi * j / Ly, c, 1.0));
      }
  return out;
}

inline double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

}  // namespace peristep::learning::testing
