#pragma once
// Orthonormal polynomials of the two laws, in long double: the common ground of the Gauss rules
// (Golub-Welsch and Newton polishing) and of the nested (Kronrod-Patterson) extensions.
#include <vector>

#include "rule1d.hpp"

namespace peristep::sampling::detail {

using Real = long double;

// Both weights are symmetric, so the three-term recurrence has no diagonal term:
//   x p_k(x) = s_{k+1} p_{k+1}(x) + s_k p_{k-1}(x),  p_0 = 1 (probability measure), p_{-1} = 0.
// Normal: p_k = He_k / sqrt(k!), s_k = sqrt(k). Uniform: p_k = sqrt(2k+1) P_k, s_k = k / sqrt(4k^2 - 1).
Real recurrenceCoefficient(Law law, int k);

struct PolynomialValue {
  Real value, derivative;
};
// p_n(x) and p_n'(x) by the recurrence.
PolynomialValue orthonormalPolynomial(Law law, int n, Real x);

// 1 / sum_{k<n} p_k(x)^2: the Gauss weight of the node x of the n-point rule (Christoffel function).
// Unlike the squared eigenvector entries of Golub-Welsch, it keeps full relative accuracy for the
// tiny weights of far Gauss-Hermite nodes, which matter for high moments.
Real christoffelWeight(Law law, int n, Real x);

// p_0(x), ..., p_n(x).
std::vector<Real> orthonormalPolynomials(Law law, int n, Real x);

}  // namespace peristep::sampling::detail
