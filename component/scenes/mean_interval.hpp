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

// t_{0.975, dof} by the Cornish-Fisher expansion in 1/dof (error below 2e-4 for dof >= 5; 12.706 and
// 4.303 are used for dof 1 and 2, the expansion's third-order value above).
double studentQuantile975(int dof);

}  // namespace peristep
