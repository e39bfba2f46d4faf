#pragma once
// The two standardized laws of a random coordinate and a one-dimensional quadrature rule for them.
#include <vector>

namespace peristep::sampling {

// Standardized laws: N(0, 1) and U[-1, 1]. The component scales them (xiScale) to the physical law.
enum class Law { Normal, Uniform };

// Nodes in ascending order; probability weights (they sum to 1: a rule computes an expectation).
struct Rule1D {
  std::vector<double> nodes, weights;
};

}  // namespace peristep::sampling
