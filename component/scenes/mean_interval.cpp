#include "scenes/mean_interval.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep {

double studentQuantile975(int dof) {
  require(dof >= 1, "Student quantile: needs at least one degree of freedom");
  constexpr double kSmall[4] = {12.7062, 4.3027, 3.1824, 2.7764};  // tables, dof 1 .. 4
  if (dof <= 4) return kSmall[dof - 1];
  const double z = 1.959963984540054, z2 = z * z, v = dof;
  const double g1 = (z2 + 1) * z / 4;
  const double g2 = ((5 * z2 + 16) * z2 + 3) * z / 96;
  const double g3 = (((3 * z2 + 19) * z2 + 17) * z2 - 15) * z / 384;
  const double g4 = ((((79 * z2 + 776) * z2 + 1482) * z2 - 1920) * z2 - 945) * z / 92160;
  return z + g1 / v + g2 / (v * v) + g3 / (v * v * v) + g4 / (v * v * v * v);
}

MeanInterval meanInterval(std::span<const double> values) {
  require(values.size() >= 2, "mean interval: needs two or more values");
  const double m = static_cast<double>(values.size());
  double mean = 0;
  for (double v : values) mean += v;
  mean /= m;
  double ss = 0;
  for (double v : values) ss += (v - mean) * (v - mean);
  MeanInterval out;
  out.mean = mean;
  out.standardDeviation = std::sqrt(ss / (m - 1));
  out.halfWidth = studentQuantile975(static_cast<int>(values.size()) - 1) * out.standardDeviation / std::sqrt(m);
  return out;
}

}  // namespace peristep
