#include "scenes/cyclic_fit.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep {

CyclicFit fitCyclicCurve(std::span<const double> stress, std::span<const double> plastic) {
  require(stress.size() == plastic.size() && stress.size() >= 2, "cyclic fit: needs two or more loops");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(stress.size());
  for (std::size_t i = 0; i < stress.size(); ++i) {
    require(stress[i] > 0 && plastic[i] > 0, "cyclic fit: stress and plastic strain amplitudes must be positive");
    const double x = std::log(plastic[i]), y = std::log(stress[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double spread = sxx - sx * sx / m;
  require(spread > 0, "cyclic fit: the plastic strain amplitudes must not all be equal");
  CyclicFit fit;
  fit.exponent = (sxy - sx * sy / m) / spread;
  fit.coefficient = std::exp((sy - fit.exponent * sx) / m);
  return fit;
}

}  // namespace peristep
