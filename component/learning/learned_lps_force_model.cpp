#include "learning/learned_lps_force_model.hpp"

#include <vector>

#include "learning/lps_residual.hpp"

namespace peristep::learning {

LearnedLpsForceModel::LearnedLpsForceModel(PeriodicLattice lattice, LatticeStencil stencil, BernsteinKernel kernel,
                                           double lambda, double mu, double thickness)
    : lattice_(lattice), stencil_(std::move(stencil)), kernel_(std::move(kernel)), lambda_(lambda), mu_(mu),
      thickness_(thickness) {}

void LearnedLpsForceModel::force(const double* u, double* f) {
  const std::vector<double> L =
      applyLearnedLps(lattice_, stencil_, kernel_, lambda_, mu_, std::vector<double>(u, u + 2 * points()));
  for (std::size_t i = 0; i < L.size(); ++i) f[i] = -L[i];
}

Eigen::SparseMatrix<double> LearnedLpsForceModel::tangent(const double*) {
  const std::size_t n = 2 * points();
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> e(n, 0.0), f(n);
  for (std::size_t c = 0; c < n; ++c) {
    e[c] = 1.0;
    force(e.data(), f.data());
    e[c] = 0.0;
    for (std::size_t r = 0; r < n; ++r)
      if (f[r] != 0.0) entries.emplace_back(static_cast<int>(r), static_cast<int>(c), f[r]);
  }
  Eigen::SparseMatrix<double> T(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  T.setFromTriplets(entries.begin(), entries.end());
  return T;
}

double LearnedLpsForceModel::energy(const double* u) {
  std::vector<double> f(2 * points());
  force(u, f.data());
  double e = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) e -= 0.5 * u[i] * f[i];
  return e * pointVolume(0);
}

}  // namespace peristep::learning
