#include "multilevel.hpp"

#include <cmath>
#include <stdexcept>

namespace peristep::sampling {

LevelStatistics levelStatistics(std::span<const double> values) {
  LevelStatistics s;
  s.count = values.size();
  if (values.empty()) return s;
  for (double v : values) s.mean += v;
  s.mean /= static_cast<double>(values.size());
  if (values.size() < 2) return s;
  for (double v : values) s.variance += (v - s.mean) * (v - s.mean);  // two passes: no cancellation
  s.variance /= static_cast<double>(values.size() - 1);
  return s;
}

std::vector<std::size_t> optimalCounts(std::span<const double> variance, std::span<const double> cost, double se,
                                       std::size_t least) {
  if (variance.size() != cost.size()) throw std::invalid_argument("one cost per level's variance");
  if (!(se > 0)) throw std::invalid_argument("the target standard error must be positive");
  double sum = 0;
  for (std::size_t l = 0; l < variance.size(); ++l) {
    if (!(cost[l] > 0) || !(variance[l] >= 0)) throw std::invalid_argument("costs must be positive, variances >= 0");
    sum += std::sqrt(variance[l] * cost[l]);
  }
  std::vector<std::size_t> n(variance.size(), least);
  for (std::size_t l = 0; l < variance.size(); ++l) {
    const double optimal = std::ceil(std::sqrt(variance[l] / cost[l]) * sum / (se * se));
    if (optimal > static_cast<double>(least)) n[l] = static_cast<std::size_t>(optimal);
  }
  return n;
}

MultilevelEstimate combine(std::span<const LevelStatistics> levels) {
  MultilevelEstimate e;
  double variance = 0;
  for (const LevelStatistics& s : levels) {
    e.mean += s.mean;
    if (s.count > 0) variance += s.variance / static_cast<double>(s.count);
  }
  e.se = std::sqrt(variance);
  return e;
}

}  // namespace peristep::sampling
