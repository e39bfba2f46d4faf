#include "random/randomized_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/errors.hpp"

namespace peristep {
namespace {

// Standard normal test matrix by Box-Muller on mt19937_64: std::normal_distribution differs between
// standard libraries, this does not.
Eigen::MatrixXd gaussianMatrix(std::size_t rows, std::size_t cols, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto uniform = [&rng] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };  // (0, 1)
  Eigen::MatrixXd G(rows, cols);
  double* g = G.data();
  const std::size_t size = rows * cols;
  for (std::size_t i = 0; i < size; i += 2) {
    const double radius = std::sqrt(-2.0 * std::log(uniform())), angle = 2.0 * std::numbers::pi * uniform();
    g[i] = radius * std::cos(angle);
    if (i + 1 < size) g[i + 1] = radius * std::sin(angle);
  }
  return G;
}

// Orthonormal basis of the columns of Y (thin Q of a Householder QR: stable even when Y is rank
// deficient, where the extra columns still come out orthonormal).
Eigen::MatrixXd orthonormalize(const Eigen::MatrixXd& Y) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Y);
  return qr.householderQ() * Eigen::MatrixXd::Identity(Y.rows(), Y.cols());
}

Eigen::MatrixXd product(const BlockProduct& apply, const Eigen::MatrixXd& X) {
  Eigen::MatrixXd AX;
  apply(X, AX);
  if (AX.rows() != X.rows() || AX.cols() != X.cols())
    throw SolverFailure("randomized eigensolver: the block product returned " + std::to_string(AX.rows()) + " x " +
                        std::to_string(AX.cols()) + " for a block of " + std::to_string(X.rows()) + " x " +
                        std::to_string(X.cols()));
  if (!AX.allFinite()) throw SolverFailure("randomized eigensolver: the block product is not finite (NaN or Inf)");
  return AX;
}

}  // namespace

EigenPairs leadingPairs(const Eigen::VectorXd& ascendingValues, const Eigen::MatrixXd& vectors, std::size_t k) {
  const auto n = ascendingValues.size();
  k = std::min<std::size_t>(k, static_cast<std::size_t>(n));
  EigenPairs out{Eigen::VectorXd(k), Eigen::MatrixXd(vectors.rows(), k)};
  for (std::size_t c = 0; c < k; ++c) {
    const auto src = n - 1 - static_cast<Eigen::Index>(c);
    out.values[c] = ascendingValues[src];
    Eigen::Index big = 0;
    vectors.col(src).cwiseAbs().maxCoeff(&big);
    out.vectors.col(c) = vectors(big, src) < 0 ? Eigen::VectorXd(-vectors.col(src)) : Eigen::VectorXd(vectors.col(src));
  }
  return out;
}

EigenPairs denseEigen(const Eigen::MatrixXd& A, std::size_t k) {
  require(A.rows() == A.cols(), "dense eigensolver: the matrix must be square");
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(A);
  if (solver.info() != Eigen::Success) throw SolverFailure("dense eigensolver: no convergence");
  return leadingPairs(solver.eigenvalues(), solver.eigenvectors(), k);
}

EigenPairs randomizedEigen(std::size_t n, const BlockProduct& apply, const RandomizedEigenOptions& o) {
  require(n > 0, "randomized eigensolver: the operator has no rows");
  require(o.modes > 0 && o.modes <= n, "randomized eigensolver: modes must lie in [1, " + std::to_string(n) +
                                           "], got " + std::to_string(o.modes));
  require(static_cast<bool>(apply), "randomized eigensolver: no block product given");
  const std::size_t l = std::min(n, o.modes + o.oversampling);

  // Range finder with subspace iteration, re-orthonormalizing after every product so that the
  // columns do not all collapse onto the leading eigenvector (HMT Algorithm 4.4; A = A^T).
  Eigen::MatrixXd Q = orthonormalize(product(apply, gaussianMatrix(n, l, o.seed)));
  for (std::size_t i = 0; i < o.powerIterations; ++i) Q = orthonormalize(product(apply, Q));

  // Rayleigh-Ritz: eigenpairs of the l x l projection B = Q^T A Q, lifted back by Q.
  const Eigen::MatrixXd AQ = product(apply, Q);
  Eigen::MatrixXd B = Q.transpose() * AQ;
  B = 0.5 * (B + B.transpose()).eval();  // round-off makes the projection slightly unsymmetric
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> small(B);
  if (small.info() != Eigen::Success) throw SolverFailure("randomized eigensolver: Rayleigh-Ritz step failed");
  return leadingPairs(small.eigenvalues(), Q * small.eigenvectors(), o.modes);
}

}  // namespace peristep
