#pragma once
// Mean of independent realizations with the 95% confidence interval of the mean (Student t).
#include <span>

namespace peristep {

struct MeanInterval {
  double mean = 0;
  double halfWidth = 0;  // 95%: t_{0.975, m-1} s / sqrt(m)
  double standardDeviation = 0;
};

// Needs at least two values.
MeanInterval meanInterval(std::span<const double> values);

// t_{0.975, dof}: tabulated for dof 1 .. 4, above by the Cornish-Fisher expansion to 1/dof^4 (error
// below 4e-4 at dof 5, below 2e-5 from dof 29 on).
double studentQuantile975(int dof);

}  // namespace peristep
