#pragma once
// Exact moments of the standardized laws and quadrature of monomials, for the sampling-rule tests.
// Written independently of the library (no orthogonal polynomials, no recurrences shared with it).
#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "sampling/rule1d.hpp"
#include "sampling/sample_set.hpp"

namespace sampling_test {

using peristep::sampling::Law;
using peristep::sampling::Rule1D;
using peristep::sampling::SampleSet;

// E[x^k]: N(0,1) -> (k-1)!! for even k; U[-1,1] -> 1/(k+1) for even k; 0 for odd k.
inline double exactMoment(Law law, int k) {
  if (k % 2 == 1) return 0;
  if (law == Law::Uniform) return 1.0 / (k + 1);
  double m = 1;
  for (int j = k - 1; j > 1; j -= 2) m *= j;
  return m;
}

inline double exactMoment(std::span<const Law> laws, const std::vector<int>& exponents) {
  double m = 1;
  for (std::size_t d = 0; d < laws.size(); ++d) m *= exactMoment(laws[d], exponents[d]);
  return m;
}

struct Quadrature {
  double value = 0;  // sum_k w_k f(x_k)
  double scale = 0;  // sum_k |w_k f(x_k)|: the size of the rounding error of `value`
};

inline Quadrature integrate(const Rule1D& rule, int k) {
  Quadrature q;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const double term = rule.weights[i] * std::pow(rule.nodes[i], k);
    q.value += term;
    q.scale += std::abs(term);
  }
  return q;
}

inline Quadrature integrate(const SampleSet& set, const std::vector<int>& exponents) {
  Quadrature q;
  for (std::size_t k = 0; k < set.size(); ++k) {
    double f = 1;
    const auto x = set.point(k);
    for (std::size_t d = 0; d < set.dims; ++d) f *= std::pow(x[d], exponents[d]);
    q.value += set.weights[k] * f;
    q.scale += std::abs(set.weights[k] * f);
  }
  return q;
}

// |Q - I| relative to the larger of |I| and the rounding scale of Q.
inline double relativeError(const Quadrature& q, double exact) {
  return std::abs(q.value - exact) / std::max({std::abs(exact), q.scale, 1e-300});
}

// Calls visit(exponents) for every exponent vector of `dims` entries with total degree <= maxDegree.
inline void forEachMonomial(std::size_t dims, int maxDegree, const std::function<void(const std::vector<int>&)>& visit) {
  std::vector<int> e(dims, 0);
  std::function<void(std::size_t, int)> recurse = [&](std::size_t d, int budget) {
    if (d == dims) {
      visit(e);
      return;
    }
    for (int a = 0; a <= budget; ++a) {
      e[d] = a;
      recurse(d + 1, budget - a);
    }
    e[d] = 0;
  };
  recurse(0, maxDegree);
}

inline int totalDegree(const std::vector<int>& e) {
  int s = 0;
  for (const int a : e) s += a;
  return s;
}

}  // namespace sampling_test
