#include "fracture/toughness.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace peristep {

double centreLineLength(const PointCloud& c, const Neighbours& nb, const std::vector<std::size_t>& bonds,
                        double x0, double y0, double xEnd) {
  std::map<long, std::pair<double, int>> columns;  // column -> (sum of midpoint y, count)
  for (std::size_t k : bonds) {
    const std::size_t p = nb.owner(k), q = nb.index[k];
    const double mx = 0.5 * (c.x[p] + c.x[q]);
    if (mx < x0 || mx > xEnd) continue;
    auto& [sum, count] = columns[std::lround((mx - x0) / c.h)];
    sum += 0.5 * (c.y[p] + c.y[q]);
    ++count;
  }
  double length = 0, x = x0, y = y0;
  for (const auto& [column, value] : columns) {
    const double cx = std::min(x0 + static_cast<double>(column) * c.h, xEnd), cy = value.first / value.second;
    length += std::hypot(cx - x, cy - y);
    x = cx;
    y = cy;
  }
  return length;
}

CrackShares crackShares(const Neighbours& nb, const std::vector<std::size_t>& bonds,
                        const std::vector<std::uint8_t>& crystal, double length) {
  CrackShares s;
  if (bonds.empty()) return s;
  const double each = length / static_cast<double>(bonds.size());
  for (std::size_t k : bonds) {
    const int phases = crystal[nb.owner(k)] + crystal[nb.index[k]];
    (phases == 0 ? s.glass : phases == 2 ? s.crystal : s.interface) += each;
  }
  return s;
}

double crackEnergy(const Neighbours& nb, const std::vector<std::size_t>& bonds,
                   const std::vector<double>& G, double length) {
  if (bonds.empty()) return 0.0;
  double sum = 0;
  for (std::size_t k : bonds) sum += 0.5 * (G[nb.owner(k)] + G[nb.index[k]]);
  return sum / static_cast<double>(bonds.size()) * length;
}

double toughnessKIC(double GIC, double f, const PhaseConstants& m) {
  const double Eeff = (1.0 - f) * m.E1 + f * m.E2;
  return std::sqrt(GIC * Eeff / (1.0 - m.nu * m.nu));
}

}  // namespace peristep
