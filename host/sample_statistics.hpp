#pragma once
// Moments of a sampled quantity.
//  - Any rule, with its weights, 000:(3.10)-(3.11): E[q] = sum mu_k q_k and sigma[q]^2 = sum mu_k q_k^2 -
//    E[q]^2, evaluated as sum mu_k (q_k - E[q])^2 (the same when the weights sum to 1, without the
//    cancellation). Sparse-grid weights can be negative, so this direct estimate can come out negative
//    where the true variance is tiny: it is clamped at 0 and counted.
//  - Smolyak rules also: the variance of the sparse pseudo-spectral surrogate (sampling/sparse_grid.hpp),
//    a sum of squared coefficients, never negative.
//  - Monte Carlo (Q equal weights 1/Q) also: standard errors. With m2 = sum (q_k - mean)^2 / Q (the
//    variance reported, 000:(3.11)), s^2 = Q m2 / (Q - 1), m4 = sum (q_k - mean)^4 / Q:
//      se(mean) = s / sqrt(Q);  se(variance) = sqrt((m4 - m2^2) / Q) (the large-Q variance of m2);
//      se(std) = se(variance) / (2 std) (delta method); 95% interval of the mean: mean -+ 1.96 se(mean).
//    Q = 1 gives no standard error (NaN).
#include <cstddef>
#include <vector>

#include "sampling/sparse_grid.hpp"

namespace peristep::host {

struct Moments {
  std::vector<double> mean, std;
  std::size_t clamped = 0;  // entries whose direct variance estimate was negative
  std::vector<double> pceStd;                // Smolyak: sqrt(sum_{a != 0} c_a^2); empty otherwise
  std::vector<double> seMean, seVar, seStd;  // Monte Carlo; empty otherwise
};

// values[k] holds sample k (all the same length); weights[k] its weight.
Moments weightedMoments(const std::vector<const std::vector<double>*>& values, const std::vector<double>& weights);

// Fills m.pceStd from the samples (indexed as the projection's) of a Smolyak rule.
void addPceStd(Moments& m, const std::vector<const std::vector<double>*>& values,
               const sampling::SparseProjection& projection);

// Fills m.seMean, seVar, seStd for equally weighted samples (m from weightedMoments on the same values).
void addStandardErrors(Moments& m, const std::vector<const std::vector<double>*>& values);

// Half width of the 95% interval of the mean from its standard error (normal quantile 1.959964).
double interval95(double seMean);

}  // namespace peristep::host
