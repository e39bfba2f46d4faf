#pragma once
// Potential functions of the nonlinear state-based model of 001 Sec. 2.1 and Sec. 6.
#include <cmath>
#include <limits>

namespace peristep {

// 001 Sec. 6: influence function J(r) = 1 - r on the unit ball, zero outside.
inline double influenceJ(double r) { return r < 1.0 ? 1.0 - r : 0.0; }

// 001:(3), 001 Sec. 6: f(r) = c (1 - exp(-beta r^2)), r = sqrt(|xi|) S. Convex up to the inflection
// point r* = 1/sqrt(2 beta) (critical strain S_c = r*/sqrt(|xi|), 001:(6)), softening beyond.
struct TensilePotential {
  double c = 0, beta = 0;

  double value(double r) const { return c * (1.0 - std::exp(-beta * r * r)); }
  double slope(double r) const { return 2.0 * c * beta * r * std::exp(-beta * r * r); }
  double curvature(double r) const { return 2.0 * c * beta * (1.0 - 2.0 * beta * r * r) * std::exp(-beta * r * r); }
  double inflection() const { return 1.0 / std::sqrt(2.0 * beta); }
};

// 001:(4), Fig. 2: hydrostatic potential g(theta).
//  - quadratic: g = C theta^2/2 (001 Sec. 6), no softening;
//  - convex-concave: g = C/(2 b) (1 - exp(-b theta^2)) with b = b+ for theta >= 0 and b- below, so that
//    g''(0) = C as for the quadratic law, the inflection points are theta_c^+- = +-1/sqrt(2 b+-) (001:(9)),
//    g is bounded and its first three derivatives are bounded and continuous (001:(10)).
enum class HydrostaticLaw { Quadratic, ConvexConcave };

struct HydrostaticPotential {
  HydrostaticLaw law = HydrostaticLaw::Quadratic;
  double C = 0;
  double bPlus = 0, bMinus = 0;  // convex-concave only

  double b(double t) const { return t >= 0 ? bPlus : bMinus; }
  double value(double t) const {
    if (law == HydrostaticLaw::Quadratic) return 0.5 * C * t * t;
    return C / (2.0 * b(t)) * (1.0 - std::exp(-b(t) * t * t));
  }
  double slope(double t) const {
    if (law == HydrostaticLaw::Quadratic) return C * t;
    return C * t * std::exp(-b(t) * t * t);
  }
  double curvature(double t) const {
    if (law == HydrostaticLaw::Quadratic) return C;
    return C * (1.0 - 2.0 * b(t) * t * t) * std::exp(-b(t) * t * t);
  }
  bool active() const { return C != 0.0; }
};

}  // namespace peristep
