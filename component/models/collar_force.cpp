#include "models/collar_force.hpp"

#include <cmath>

#include "models/lps_material.hpp"

namespace peristep {

std::array<double, 2> collarForce(const LpsDiscretization& d, const std::vector<double>& lambda,
                                  const std::vector<double>& mu, const std::vector<double>& u,
                                  const std::vector<double>& x, const std::vector<std::uint8_t>& collar,
                                  const std::vector<std::uint8_t>* intact) {
  const PointCloud& c = d.cloud;
  const Neighbours& nb = d.neighbours;
  const auto theta = [&](std::size_t p) { return d.dofs.theta[p] >= 0 ? x[static_cast<std::size_t>(d.dofs.theta[p])] : 0.0; };
  std::array<double, 2> F{0, 0};
  for (std::size_t p : c.domain)
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      const std::uint32_t q = nb.index[k];
      if (!collar[q] || (intact && !(*intact)[k])) continue;
      // Force of bond p-q on p: the negated summand of 000:(3.19).
      const double z[2] = {c.x[q] - c.x[p], c.y[q] - c.y[p]};
      const double r2 = z[0] * z[0] + z[1] * z[1];
      const double Kw = 3.0 / (M_PI * std::pow(c.delta, 3) * std::sqrt(r2)) * d.weights[k];
      const double lam = harmonicMean(lambda[p], lambda[q]);
      const double m = harmonicMean(mu[p], mu[q]);
      const double du[2] = {u[2 * q] - u[2 * p], u[2 * q + 1] - u[2 * p + 1]};
      const double zdu = z[0] * du[0] + z[1] * du[1];
      for (int a = 0; a < 2; ++a)
        F[static_cast<std::size_t>(a)] += c.h * c.h * Kw * ((lam - m) * z[a] * (theta(p) + theta(q)) + 8.0 * m * z[a] * zdu / r2);
    }
  return F;
}

}  // namespace peristep
