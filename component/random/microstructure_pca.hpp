#pragma once
// Principal component analysis of microstructure realizations (000 Sec. 5, (5.4)-(5.5)) without the
// n x M data matrix: every product of the sample covariance
//
//   C = 1/(n-1) sum_j (x_j - m)(x_j - m)^T
//
// with a block X streams the n realizations again (the generator regenerates realization j from its
// seed), and the randomized eigensolver needs q + 2 such products.
//
// Reading of 000:(5.5). The paper takes xi_k ~ N(0, lambda_k^2) "with lambda_k the k-th eigenvalue in
// PCA". The PCA scores a_jk = V_k^T (x_j - m) of (5.4) have sample variance equal to the k-th eigenvalue
// of C, so the consistent model is xi_k ~ N(0, lambda_k) with lambda_k that eigenvalue: standard
// deviation sqrt(lambda_k). Here `variances` holds those eigenvalues, and expand() takes standardized
// coordinates eta_k ~ N(0, 1), xi_k = sqrt(lambda_k) eta_k.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Dense>

namespace peristep {

// Fills `out` (M values) with realization j, e.g. the crystal indicator 000:(5.1) regenerated from
// seed base + j. Called concurrently from several threads: it must be safe to do so, and must give the
// same values for the same j on every call.
using RealizationGenerator = std::function<void(std::size_t j, std::span<double> out)>;

struct PcaSpec {
  std::size_t values = 0;           // M: values per realization
  std::size_t realizations = 0;     // n (000 Sec. 5: 20,000)
  std::size_t modes = 20;           // k (000 Sec. 5: 20)
  // The indicator's covariance spectrum is flat (lambda_1 / lambda_20 ~ 1.1 on the glass-ceramic grid),
  // which slows subspace iteration: p = 20, q = 6 capture 95-97 % of the optimal 20-mode variance at
  // h = 16 um, n = 20,000 / 2,000 (p = 10, q = 2: 87 %; docs/decisions/0019-random-field-solvers.md).
  std::size_t oversampling = 20;    // p
  std::size_t powerIterations = 6;  // q: passes over the realizations = q + 2
  std::uint64_t seed = 1;           // of the randomized test matrix (not of the realizations)
};

struct PcaModes {
  Eigen::VectorXd mean;       // m (M)
  Eigen::MatrixXd modes;      // V (M x k), orthonormal columns
  Eigen::VectorXd variances;  // eigenvalues of C, descending (k)
  double totalVariance = 0;   // trace of C
  std::size_t realizations = 0;
  std::size_t passes = 0;     // streams over the realizations that were made

  std::size_t size() const { return static_cast<std::size_t>(variances.size()); }
  // sum of the kept eigenvalues / trace C
  double retainedFraction() const;
  // m + sum_k sqrt(lambda_k) eta_k V_k for standardized eta (000:(5.4)-(5.5) with xi_k = sqrt(lambda_k) eta_k).
  Eigen::VectorXd expand(std::span<const double> eta) const;
};

// Streams realizations 0 .. n-1 through the randomized eigensolver. OpenMP over realizations; the
// partial sums of fixed chunks are added in chunk order, so the result is the same for any number of
// threads. Mean and trace come from the first pass. Throws InvalidInput for an inconsistent spec and
// rethrows what the generator throws (also from inside the parallel loop).
PcaModes streamedPca(const PcaSpec& spec, const RealizationGenerator& generate);

}  // namespace peristep
