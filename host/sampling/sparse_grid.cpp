#include "sparse_grid.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gauss_rules.hpp"
#include "nested_rules.hpp"
#include "orthogonal_polynomials.hpp"

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

int sparseGridRuleDegree(Law law, int level, Family family) {
  return family == Family::Gauss ? 2 * (2 * level + 1) - 1 : nestedRuleDegree(law, level);
}

namespace {

// The terms of A(L, N) (000:(3.8)): calls visit(index, coefficient, digit, point, weight) for every node
// of every tensor rule U^{i_1} x ... x U^{i_N} in the combination, multi-indices in lexicographic order,
// nodes with the last coordinate fastest; digit[d] is the node's position in rule i_d, weight the
// tensor rule's own weight (without the combination coefficient).
template <class Visit>
void forEachTensorNode(std::span<const Law> laws, int level, Family family, Visit visit) {
  if (level < 0) throw std::invalid_argument("smolyakGrid: negative level " + std::to_string(level));
  const int dims = static_cast<int>(laws.size());
  // Each 1D rule computed once, so that shared nodes (0, and all nested ones) are identical doubles.
  std::vector<Rule1D> normal, uniform;
  for (int l = 0; l <= level; ++l) {
    normal.push_back(sparseGridRule(Law::Normal, l, family));
    uniform.push_back(sparseGridRule(Law::Uniform, l, family));
  }
  std::vector<double> point(dims);
  auto addTensorProduct = [&](const std::vector<int>& index) {
    int total = 0;
    for (const int l : index) total += l;
    if (total < level - dims + 1) return;
    const int gap = level - total;
    const double coefficient = (gap % 2 == 0 ? 1 : -1) * binomial(dims - 1, gap);
    std::vector<std::size_t> digit(dims, 0);
    for (;;) {
      long double w = 1;
      for (int d = 0; d < dims; ++d) {
        const Rule1D& rule = (laws[d] == Law::Normal ? normal : uniform)[index[d]];
        point[d] = rule.nodes[digit[d]];
        w *= rule.weights[digit[d]];
      }
      visit(index, coefficient, digit, point, w);
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
}

}  // namespace

SampleSet smolyakGrid(std::span<const Law> laws, int level, Family family) {
  if (level < 0) throw std::invalid_argument("smolyakGrid: negative level " + std::to_string(level));
  if (laws.empty()) return SampleSet{0, {}, {1}};  // nothing random: one empty point carries all the weight
  SampleSet set;
  set.dims = laws.size();
  std::map<std::vector<double>, std::size_t> slot;  // merged point -> its position in the set
  std::vector<long double> weights;                  // accumulated in long double: the terms cancel
  forEachTensorNode(laws, level, family,
                    [&](const std::vector<int>&, double coefficient, const std::vector<std::size_t>&,
                        const std::vector<double>& point, long double w) {
                      const auto [it, inserted] = slot.try_emplace(point, weights.size());
                      if (inserted) {
                        set.points.insert(set.points.end(), point.begin(), point.end());
                        weights.push_back(coefficient * w);
                      } else {
                        weights[it->second] += coefficient * w;
                      }
                    });
  set.weights.assign(weights.begin(), weights.end());
  return set;
}

SparseProjection sparsePseudoSpectral(std::span<const Law> laws, int level, Family family) {
  if (level < 0) throw std::invalid_argument("sparsePseudoSpectral: negative level " + std::to_string(level));
  SparseProjection projection;
  if (laws.empty()) {
    projection.coefficients = 1;
    projection.terms.push_back({0, 0, 1.0});
    return projection;
  }
  const std::size_t dims = laws.size();
  std::map<std::vector<double>, std::size_t> slot;  // the same numbering as smolyakGrid
  std::map<std::vector<int>, std::size_t> coefficient{{std::vector<int>(dims, 0), 0}};
  std::map<std::pair<std::size_t, std::size_t>, long double> factor;  // summed in long double: they cancel
  std::vector<int> highest(dims), alpha(dims);
  forEachTensorNode(
      laws, level, family,
      [&](const std::vector<int>& index, double combination, const std::vector<std::size_t>&,
          const std::vector<double>& point, long double w) {
        const std::size_t sample = slot.try_emplace(point, slot.size()).first->second;
        // p_0..p_{a_d} at this node, for the a_d <= degree/2 the 1D rule i_d keeps.
        std::vector<std::vector<detail::Real>> p(dims);
        for (std::size_t d = 0; d < dims; ++d) {
          highest[d] = sparseGridRuleDegree(laws[d], index[d], family) / 2;
          p[d] = detail::orthonormalPolynomials(laws[d], highest[d], point[d]);
        }
        std::fill(alpha.begin(), alpha.end(), 0);
        for (;;) {
          long double psi = combination * w;
          for (std::size_t d = 0; d < dims; ++d) psi *= p[d][alpha[d]];
          const std::size_t c = coefficient.try_emplace(alpha, coefficient.size()).first->second;
          factor[{c, sample}] += psi;
          std::size_t d = dims;
          while (d > 0 && ++alpha[d - 1] > highest[d - 1]) alpha[--d] = 0;
          if (d == 0) break;
        }
      });
  projection.coefficients = coefficient.size();
  for (const auto& [where, f] : factor)
    projection.terms.push_back({where.first, where.second, static_cast<double>(f)});
  return projection;
}

}  // namespace peristep::sampling
