#include "models/ramberg_osgood.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace peristep {

double RambergOsgood::strain(double stress) const {
  const double plastic = yieldOffset * std::pow(std::abs(stress) / yieldStress, exponent);
  return stress / youngsModulus + std::copysign(plastic, stress);
}

double RambergOsgood::stressAtTangent(double tangent) const {
  require(tangent > 0 && tangent < youngsModulus, "Ramberg-Osgood: tangent modulus outside (0, E)");
  const double compliance = 1.0 / tangent - 1.0 / youngsModulus;
  return yieldStress * std::pow(compliance * yieldStress / (yieldOffset * exponent), 1.0 / (exponent - 1.0));
}

double RambergOsgood::tangent(double stress) const {
  return 1.0 / (1.0 / youngsModulus + yieldOffset * exponent * std::pow(stress / yieldStress, exponent - 1.0) / yieldStress);
}

double RambergOsgood::stress(double target) const {
  require(target >= 0, "Ramberg-Osgood: stress(eps) is evaluated for eps >= 0");
  // eps(sigma) is convex for sigma >= 0, so Newton from above the root converges monotonically; both
  // terms of eps(sigma) alone bound the root from above.
  double s = std::min(youngsModulus * target, yieldStress * std::pow(target / yieldOffset, 1.0 / exponent));
  for (int it = 0; it < 100; ++it) {
    const double ds = (strain(s) - target) * tangent(s);
    s -= ds;
    if (std::abs(ds) <= 1e-14 * s) break;
  }
  return s;
}

double RambergOsgood::softness(double E) const {
  const double ef = failureStrain, sf = failureStress;
  const double brittle = 0.5 * E * ef * ef;  // 002:(17) denominator: the brittle-elastic energy at eps_f
  const double soft = brittle - sf * ef + sf * sf / (2 * E) +
                      yieldOffset * yieldStress / (exponent + 1) * std::pow(sf / yieldStress, exponent + 1);
  return soft / brittle;
}

double RambergOsgood::masingCoefficient() const { return yieldStress * std::pow(yieldOffset, -1.0 / exponent); }

RambergOsgood gamutMaterial1() { return {71.6e9, 538.6e6, 665.8e6, 0.115, 17.8702, 0.002}; }
RambergOsgood gamutMaterial2() { return {115.7e9, 867e6, 933e6, 0.516, 47.61, 0.002}; }

}  // namespace peristep
