#pragma once
// Points of the random space with their weights: what a sample loop runs over. Expectations are
// sum_k weights[k] q(point(k)) (000:(3.10)-(3.11)).
#include <cstddef>
#include <span>
#include <vector>

namespace peristep::sampling {

struct SampleSet {
  std::size_t dims = 0;
  std::vector<double> points;   // row-major, size() x dims
  std::vector<double> weights;  // sum to 1 (Smolyak: some may be negative)

  std::size_t size() const { return weights.size(); }
  std::span<const double> point(std::size_t k) const { return {points.data() + k * dims, dims}; }
};

}  // namespace peristep::sampling
