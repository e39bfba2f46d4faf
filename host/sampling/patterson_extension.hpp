#pragma once
// Kronrod-Patterson extension of a node set for one law: add nodes so that the interpolatory rule
// on the union has the highest possible degree. Gauss-Patterson (Legendre) and Genz-Keister
// (Hermite) sequences are built by repeating it; nothing here is tabulated.
#include <vector>

#include "orthogonal_polynomials.hpp"

namespace peristep::sampling::detail {

// The `count` new nodes (ascending) for the symmetric node set `nodes` (count even): the roots of the
// degree-`count` polynomial q with E[q(x) pi(x) x^k] = 0 for k < count, pi(x) = prod_i (x - x_i).
// The rule on the union then integrates degree |nodes| + 2 count - 1 exactly (one more by symmetry).
// std::runtime_error when no such real extension exists: complex roots, roots on existing nodes, or
// outside [-1, 1] for the uniform law.
std::vector<Real> pattersonNodes(Law law, const std::vector<Real>& nodes, int count);

// Weights of the interpolatory rule on distinct nodes: w_i = E[l_i(x)], l_i the Lagrange polynomials
// (integrated exactly by a Gauss rule of sufficient degree).
std::vector<Real> interpolatoryWeights(Law law, const std::vector<Real>& nodes);

// max_{k <= degree} |sum_i w_i p_k(x_i) - E[p_k]|, p_k orthonormal (E[p_k] = 1 for k = 0, else 0):
// how far the rule is from integrating degree `degree` exactly.
Real exactnessDefect(Law law, const std::vector<Real>& nodes, const std::vector<Real>& weights, int degree);

}  // namespace peristep::sampling::detail
