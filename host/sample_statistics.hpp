#pragma once
// Moments of a sampled quantity with the rule's weights, 000:(3.10)-(3.11): E[q] = sum mu_k q_k and
// sigma[q]^2 = sum mu_k q_k^2 - E[q]^2, evaluated as sum mu_k (q_k - E[q])^2 (the same when the
// weights sum to 1, without the cancellation). Sparse-grid weights can be negative, so the variance
// estimate can come out negative where the true one is tiny: it is clamped at 0 and counted.
#include <cstddef>
#include <vector>

namespace peristep::host {

struct Moments {
  std::vector<double> mean, std;
  std::size_t clamped = 0;  // entries whose variance estimate was negative
};

// values[k] holds sample k (all the same length); weights[k] its weight.
Moments weightedMoments(const std::vector<const std::vector<double>*>& values, const std::vector<double>& weights);

}  // namespace peristep::host
