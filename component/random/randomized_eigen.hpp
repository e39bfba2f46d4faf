#pragma once
// Leading eigenpairs of a symmetric positive semi-definite operator known only through block products
// A X (Halko, Martinsson, Tropp 2011: randomized range finder with subspace iteration, Algorithm 4.4,
// followed by Rayleigh-Ritz on Q^T A Q). Used for the KL modes of large point sets and for the streamed
// PCA of microstructure realizations, where A is never formed.
#include <cstddef>
#include <cstdint>
#include <functional>

#include <Eigen/Dense>

namespace peristep {

// Must set AX = A X for a block X of n x l columns (resizing AX as needed).
using BlockProduct = std::function<void(const Eigen::MatrixXd& X, Eigen::MatrixXd& AX)>;

struct RandomizedEigenOptions {
  std::size_t modes = 20;           // k: eigenpairs wanted
  std::size_t oversampling = 10;    // p: extra test vectors (l = k + p, capped at n)
  std::size_t powerIterations = 2;  // q: subspace iterations; the subspace error falls like
                                    // (lambda_{l+1}/lambda_k)^(q+1), eigenvalues like its square
  std::uint64_t seed = 1;           // seed of the Gaussian test matrix
};

// Eigenvalues in descending order and the matching orthonormal eigenvectors (columns). The sign of
// every vector is fixed so that its entry of largest magnitude is positive: equal inputs give equal
// outputs whichever solver produced them.
struct EigenPairs {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};

// q + 2 products with blocks of l columns. The test matrix is drawn serially from the seed, so the
// result depends only on (A, options), also when the callback runs in parallel. Throws InvalidInput
// for inconsistent options and SolverFailure when a product has the wrong shape or is not finite.
EigenPairs randomizedEigen(std::size_t n, const BlockProduct& apply, const RandomizedEigenOptions& options);

// Dense symmetric eigen-decomposition, leading k pairs, same ordering and sign convention.
EigenPairs denseEigen(const Eigen::MatrixXd& symmetric, std::size_t k);

// Orders the pairs of a self-adjoint solve (ascending) as descending, keeps k, fixes the signs.
EigenPairs leadingPairs(const Eigen::VectorXd& ascendingValues, const Eigen::MatrixXd& vectors, std::size_t k);

}  // namespace peristep
