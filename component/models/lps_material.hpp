#pragma once
// Material constants of the heterogeneous LPS model (000 Sec. 2.1, Sec. 4).
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "models/poisson_ratio.hpp"

namespace peristep {

struct Lame {
  double lambda, mu;
};

// Rejects non-physical constants: E must be positive and finite, -1 < nu < 1/2.
inline void validateElastic(double E, double nu) {
  require(std::isfinite(E) && E > 0.0, "Young's modulus must be positive and finite (got E = " + std::to_string(E) + ")");
  require(admissiblePoissonRatio(nu), "Poisson ratio must lie in (-1, 0.5) (got nu = " + std::to_string(nu) + ")");
}

// Plane strain, 000 Sec. 4: lambda = E nu/((1+nu)(1-2nu)), mu = E/(2(1+nu)).
inline Lame planeStrain(double E, double nu) {
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

// Two springs in series, 000:(2.6).
inline double harmonicMean(double a, double b) { return a + b == 0.0 ? 0.0 : 2.0 * a * b / (a + b); }

}  // namespace peristep
