#include "models/gamut_local_bonds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace peristep {

std::vector<double> nonlocalCutForces(std::span<const CutCrossing> crossings, std::span<const std::size_t> firstElement,
                                      std::span<const double> stiffness, std::span<const double> cap,
                                      std::span<const double> bondLength, std::span<const double> knots, std::size_t cuts) {
  const std::size_t m = knots.size();
  std::vector<double> change((cuts + 1) * m, 0.0), force(m);
  for (const CutCrossing& c : crossings) {
    std::fill(force.begin(), force.end(), 0.0);
    for (std::size_t e = firstElement[c.bond]; e < firstElement[c.bond + 1]; ++e)
      for (std::size_t k = 0; k < m; ++k) force[k] += std::min(stiffness[e] * bondLength[c.bond] * knots[k], cap[e]);
    for (std::size_t k = 0; k < m; ++k) {
      change[c.first * m + k] += c.multiplicity * force[k];
      change[c.end * m + k] -= c.multiplicity * force[k];
    }
  }
  std::vector<double> out(cuts * m);
  for (std::size_t k = 0; k < m; ++k) {
    double running = 0;
    for (std::size_t j = 0; j < cuts; ++j) out[j * m + k] = running += change[j * m + k];
  }
  return out;
}

LocalBundle localBundle(std::span<const double> knots, std::span<const double> remainder) {
  // The least concave majorant of (0, 0) and (knot, running maximum of the remainder, at least 0): a
  // curve an elastic-slipping bundle can follow (nondecreasing, concave), equal to the remainder
  // wherever that is already so. Where the nonlocal elements alone carry more than the point's curve
  // (a soft point among stiffer ones), the local bond keeps the stiffness of the chord instead of none.
  std::vector<double> hx{0}, hy{0};
  double running = 0;
  for (std::size_t k = 0; k < knots.size(); ++k) {
    running = std::max(running, remainder[k]);
    while (hx.size() >= 2) {
      const std::size_t a = hx.size() - 2, b = hx.size() - 1;
      // Drop b if it lies on or below the chord from a to the new point.
      if ((hy[b] - hy[a]) * (knots[k] - hx[a]) <= (running - hy[a]) * (hx[b] - hx[a])) {
        hx.pop_back();
        hy.pop_back();
      } else {
        break;
      }
    }
    hx.push_back(knots[k]);
    hy.push_back(running);
  }
  LocalBundle bundle;
  for (std::size_t i = 1; i < hx.size(); ++i) {
    const double slope = (hy[i] - hy[i - 1]) / (hx[i] - hx[i - 1]);
    const double next = i + 1 < hx.size() ? (hy[i + 1] - hy[i]) / (hx[i + 1] - hx[i]) : 0.0;
    bundle.stiffness.push_back(slope - next);
    bundle.strain.push_back(i + 1 < hx.size() ? hx[i] : std::numeric_limits<double>::infinity());
  }
  return bundle;
}

std::vector<double> localKnots(double yieldStrain, double failureStrain, int count) {
  std::vector<double> knots;
  const double from = 0.25 * yieldStrain, to = 2 * failureStrain;
  for (int k = 0; k < count; ++k) knots.push_back(from * std::pow(to / from, static_cast<double>(k) / (count - 1)));
  knots.push_back(2 * to);
  return knots;
}

}  // namespace peristep
