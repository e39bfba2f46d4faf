#include "tensor_grid.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "gauss_rules.hpp"

namespace peristep::sampling {

SampleSet tensorGrid(std::span<const Law> laws, int pointsPerDim) {
  if (pointsPerDim < 1)
    throw std::invalid_argument("tensorGrid: need at least 1 point per dimension, got " + std::to_string(pointsPerDim));
  const std::size_t dims = laws.size(), n = static_cast<std::size_t>(pointsPerDim);
  std::size_t count = 1;
  for (std::size_t d = 0; d < dims; ++d) {
    if (count > std::numeric_limits<std::size_t>::max() / n / (dims + 1))
      throw std::length_error("tensorGrid: " + std::to_string(n) + "^" + std::to_string(dims) + " points is too many");
    count *= n;
  }
  const Rule1D normal = gaussRule(Law::Normal, pointsPerDim), uniform = gaussRule(Law::Uniform, pointsPerDim);

  SampleSet set;
  set.dims = dims;
  set.points.resize(count * dims);
  set.weights.resize(count);
  std::vector<std::size_t> digit(dims, 0);  // odometer over the 1D node indices
  for (std::size_t k = 0; k < count; ++k) {
    double w = 1;
    for (std::size_t d = 0; d < dims; ++d) {
      const Rule1D& rule = laws[d] == Law::Normal ? normal : uniform;
      set.points[k * dims + d] = rule.nodes[digit[d]];
      w *= rule.weights[digit[d]];
    }
    set.weights[k] = w;
    for (std::size_t d = dims; d-- > 0;) {
      if (++digit[d] < n) break;
      digit[d] = 0;
    }
  }
  return set;
}

}  // namespace peristep::sampling
