#pragma once
// Highly accurate one-dimensional rules for expectations over a standardized random coordinate, used
// to compute the exact moments of the verification scenes (not for sampling: the host owns that).
#include <vector>

namespace peristep {

struct ProbabilityRule {
  std::vector<double> nodes, weights;  // weights sum to 1
};

// N(0, 1): trapezoidal rule on [-8, 8] with spacing 1/3. For integrands analytic in a strip
// |Im xi| < a the error decays like exp(-2 pi a / spacing) (a = 1.44 in Tests 1-3: about 1e-12),
// and the truncated tails carry exp(-32) of the mass.
ProbabilityRule normalReferenceRule();

// U[-1, 1]: n-point Gauss-Legendre (Newton iteration on the Legendre recurrence), exact to degree 2n - 1.
ProbabilityRule uniformReferenceRule(int n = 24);

}  // namespace peristep
