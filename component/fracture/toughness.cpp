#include "fracture/toughness.hpp"

#include <algorithm>
#include <cmath>

namespace peristep {

namespace {

// Owner of a CSR position, by bisection of the row offsets.
std::size_t ownerOf(const Neighbours& nb, std::size_t k) {
  return static_cast<std::size_t>(std::upper_bound(nb.offset.begin(), nb.offset.end(), k) - nb.offset.begin() - 1);
}

}  // namespace

double crackLengthPerBond(double h, double delta) { return 3.0 * std::pow(h, 4) / (2.0 * std::pow(delta, 3)); }

CrackShares crackShares(const PointCloud& c, const Neighbours& nb, const std::vector<std::size_t>& bonds,
                        const std::vector<std::uint8_t>& crystal) {
  CrackShares s;
  const double each = crackLengthPerBond(c.h, c.delta);
  for (std::size_t k : bonds) {
    const std::size_t p = ownerOf(nb, k), q = nb.index[k];
    const int phases = crystal[p] + crystal[q];
    (phases == 0 ? s.glass : phases == 2 ? s.crystal : s.interface) += each;
  }
  return s;
}

double crackEnergy(const PointCloud& c, const Neighbours& nb, const std::vector<std::size_t>& bonds,
                   const std::vector<double>& G) {
  double sum = 0;
  for (std::size_t k : bonds) sum += 0.5 * (G[ownerOf(nb, k)] + G[nb.index[k]]);
  return sum * crackLengthPerBond(c.h, c.delta);
}

double toughnessKIC(double GIC, double f, const PhaseConstants& m) {
  const double Eeff = (1.0 - f) * m.E1 + f * m.E2;
  return std::sqrt(GIC * Eeff / (1.0 - m.nu * m.nu));
}

}  // namespace peristep
