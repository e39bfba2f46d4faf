#include "random/reference_rules.hpp"

#include <cmath>
#include <numeric>

namespace peristep {

ProbabilityRule normalReferenceRule() {
  constexpr int kHalf = 24;
  constexpr double kSpacing = 1.0 / 3.0;
  ProbabilityRule r;
  for (int k = -kHalf; k <= kHalf; ++k) {
    const double x = k * kSpacing;
    r.nodes.push_back(x);
    r.weights.push_back(std::exp(-0.5 * x * x));
  }
  const double sum = std::accumulate(r.weights.begin(), r.weights.end(), 0.0);
  for (double& w : r.weights) w /= sum;
  return r;
}

ProbabilityRule uniformReferenceRule(int n) {
  ProbabilityRule r;
  r.nodes.resize(static_cast<std::size_t>(n));
  r.weights.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;  // Tricomi's initial guess
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; the recurrence gives P_n and its derivative
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    r.nodes[static_cast<std::size_t>(i)] = x;
    r.weights[static_cast<std::size_t>(i)] = 1.0 / ((1.0 - x * x) * dp * dp);  // 2/((1-x^2)P'^2), halved
  }
  return r;
}

}  // namespace peristep
