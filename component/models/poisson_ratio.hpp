#pragma once
// The admissible Poisson ratios of an isotropic elastic material, -1 < nu < 1/2, defined only here: every
// model checks nu with admissiblePoissonRatio and the FMI variables take their bounds from these constants.
#include <cmath>

namespace peristep {

inline constexpr double kMinPoissonRatio = -1.0, kMaxPoissonRatio = 0.5;

inline bool admissiblePoissonRatio(double nu) {
  return std::isfinite(nu) && nu > kMinPoissonRatio && nu < kMaxPoissonRatio;
}

}  // namespace peristep
