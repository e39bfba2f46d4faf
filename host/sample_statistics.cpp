#include "sample_statistics.hpp"

#include <cmath>

#include "host_errors.hpp"

namespace peristep::host {

Moments weightedMoments(const std::vector<const std::vector<double>*>& values, const std::vector<double>& weights) {
  if (values.empty() || values.size() != weights.size())
    throw RunError("moments need one weight per sample (" + std::to_string(weights.size()) + " weights, " +
                   std::to_string(values.size()) + " samples)");
  const std::size_t n = values.front()->size();
  Moments m;
  m.mean.assign(n, 0.0);
  m.std.assign(n, 0.0);
  for (std::size_t k = 0; k < values.size(); ++k)
    for (std::size_t i = 0; i < n; ++i) m.mean[i] += weights[k] * (*values[k])[i];  // 000:(3.10)
  for (std::size_t k = 0; k < values.size(); ++k)
    for (std::size_t i = 0; i < n; ++i) {
      const double d = (*values[k])[i] - m.mean[i];
      m.std[i] += weights[k] * d * d;  // 000:(3.11)
    }
  for (double& v : m.std) {
    if (v < 0) ++m.clamped;
    v = std::sqrt(std::max(v, 0.0));
  }
  return m;
}

}  // namespace peristep::host
