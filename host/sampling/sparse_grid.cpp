#include "sparse_grid.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gauss_rules.hpp"
#include "nested_rules.hpp"

namespace peristep::sampling {
namespace {

double binomial(int n, int k) {
  double c = 1;
  for (int j = 1; j <= k; ++j) c = c * (n - k + j) / j;
  return c;
}

// Calls visit(i) for every multi-index i >= 0 with |i| <= budget, in lexicographic order. Only
// these C(N+L, L) indices are visited (231 for N = 20, L = 2), never the full tensor index space.
template <class Visit>
void forEachIndex(std::vector<int>& index, std::size_t d, int budget, Visit& visit) {
  if (d == index.size()) {
    visit(index);
    return;
  }
  for (int l = 0; l <= budget; ++l) {
    index[d] = l;
    forEachIndex(index, d + 1, budget - l, visit);
  }
  index[d] = 0;
}

}  // namespace

Rule1D sparseGridRule(Law law, int level, Family family) {
  if (level < 0) throw std::invalid_argument("sparseGridRule: negative level " + std::to_string(level));
  return family == Family::Gauss ? gaussRule(law, 2 * level + 1) : nestedRule(law, level);
}

SampleSet smolyakGrid(std::span<const Law> laws, int level, Family family) {
  if (level < 0) throw std::invalid_argument("smolyakGrid: negative level " + std::to_string(level));
  const int dims = static_cast<int>(laws.size());
  if (dims == 0) return SampleSet{0, {}, {1}};  // nothing random: one empty point carries all the weight
  // Each 1D rule computed once, so that shared nodes (0, and all nested ones) are identical doubles.
  std::vector<Rule1D> normal, uniform;
  for (int l = 0; l <= level; ++l) {
    normal.push_back(sparseGridRule(Law::Normal, l, family));
    uniform.push_back(sparseGridRule(Law::Uniform, l, family));
  }

  SampleSet set;
  set.dims = laws.size();
  std::map<std::vector<double>, std::size_t> slot;  // merged point -> its position in the set
  std::vector<long double> weights;                  // accumulated in long double: the terms cancel
  std::vector<double> point(dims);
  auto addTensorProduct = [&](const std::vector<int>& index) {
    int total = 0;
    for (const int l : index) total += l;
    if (total < level - dims + 1) return;
    const int gap = level - total;
    const double coefficient = (gap % 2 == 0 ? 1 : -1) * binomial(dims - 1, gap);
    std::vector<std::size_t> digit(dims, 0);
    for (;;) {
      long double w = coefficient;
      for (int d = 0; d < dims; ++d) {
        const Rule1D& rule = (laws[d] == Law::Normal ? normal : uniform)[index[d]];
        point[d] = rule.nodes[digit[d]];
        w *= rule.weights[digit[d]];
      }
      const auto [it, inserted] = slot.try_emplace(point, weights.size());
      if (inserted) {
        set.points.insert(set.points.end(), point.begin(), point.end());
        weights.push_back(w);
      } else {
        weights[it->second] += w;
      }
      int d = dims - 1;
      for (; d >= 0; --d) {
        const Rule1D& rule = (laws[d] == Law::Normal ? normal : uniform)[index[d]];
        if (++digit[d] < rule.nodes.size()) break;
        digit[d] = 0;
      }
      if (d < 0) break;
    }
  };
  std::vector<int> index(dims, 0);
  forEachIndex(index, 0, level, addTensorProduct);
  set.weights.assign(weights.begin(), weights.end());
  return set;
}

}  // namespace peristep::sampling
