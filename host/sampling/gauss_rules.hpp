#pragma once
// Gauss rules for the two standardized laws: Gauss-Hermite (probabilists', weight
// e^{-x^2/2}/sqrt(2 pi)) and Gauss-Legendre (weight 1/2 on [-1, 1]). The n-point rule integrates
// polynomials of degree <= 2n-1 exactly.
#include <vector>

#include "orthogonal_polynomials.hpp"
#include "rule1d.hpp"

namespace peristep::sampling {

// points >= 1 (std::invalid_argument otherwise). Nodes ascending and symmetric (x_i = -x_{n-1-i}
// exactly), the middle node exactly 0 for odd counts, weights summing to 1.
Rule1D gaussRule(Law law, int points);

namespace detail {

struct RealRule {
  std::vector<Real> nodes, weights;
};
// The same rule in long double, for building the nested extensions on top of it.
RealRule gaussRuleReal(Law law, int points);

// Rounds a symmetric rule to double keeping the symmetry exact: the negative nodes are the negatives
// of the positive ones, mirrored weights are the mean of the pair.
Rule1D toDouble(const RealRule& rule);

}  // namespace detail
}  // namespace peristep::sampling
