// Randomized subspace iteration (random/randomized_eigen.hpp) on operators with a known spectrum.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "core/errors.hpp"
#include "random/randomized_eigen.hpp"

using namespace peristep;

namespace {

// Largest principal angle between the column spaces of two orthonormal bases: sin = ||(I - U U^T) W||_2.
double subspaceSine(const Eigen::MatrixXd& U, const Eigen::MatrixXd& W) {
  const Eigen::MatrixXd R = W - U * (U.transpose() * W);
  return Eigen::JacobiSVD<Eigen::MatrixXd>(R).singularValues()(0);
}

Eigen::MatrixXd randomOrthogonal(Eigen::Index n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd G(n, n);
  for (Eigen::Index i = 0; i < G.size(); ++i) G.data()[i] = normal(rng);
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(G);
  return qr.householderQ();
}

// A = U diag(d) U^T with d_i = 0.7^i: the spectrum and the eigenvectors are known exactly.
struct KnownSpectrum {
  Eigen::MatrixXd U;
  Eigen::VectorXd d;
  Eigen::MatrixXd A;
  explicit KnownSpectrum(Eigen::Index n) : U(randomOrthogonal(n, 7)), d(n) {
    for (Eigen::Index i = 0; i < n; ++i) d[i] = std::pow(0.7, static_cast<double>(i));
    A = U * d.asDiagonal() * U.transpose();
  }
};

}  // namespace

TEST_CASE("randomized eigensolver recovers a known geometric spectrum", "[random][eigen]") {
  const KnownSpectrum s(300);
  int products = 0;
  const BlockProduct apply = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& AX) {
    ++products;
    AX = s.A * X;
  };
  const std::size_t k = 8;
  const EigenPairs r = randomizedEigen(300, apply, {k, 10, 4, 3});
  CHECK(products == 4 + 2);  // q + 2 block products
  REQUIRE(r.values.size() == static_cast<Eigen::Index>(k));
  for (std::size_t i = 0; i < k; ++i)
    CHECK(r.values[static_cast<Eigen::Index>(i)] == Approx(s.d[static_cast<Eigen::Index>(i)]).epsilon(1e-12));
  CHECK((r.vectors.transpose() * r.vectors - Eigen::MatrixXd::Identity(k, k)).norm() < 1e-12);
  CHECK(subspaceSine(s.U.leftCols(k), r.vectors) < 1e-9);
  // Each vector individually (the spectrum is simple), with the sign convention of leadingPairs.
  const EigenPairs exact = denseEigen(s.A, k);
  CHECK((r.vectors - exact.vectors).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("without power iterations the randomized eigensolver is only as good as the range finder", "[random][eigen]") {
  // 0.7^(l - k) = 0.7^4 ~ 0.24 per product: q = 0 leaves errors a fixed-tolerance check sees, q = 6 none.
  const KnownSpectrum s(200);
  const BlockProduct apply = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& AX) { AX = s.A * X; };
  const auto error = [&](std::size_t q) {
    const EigenPairs r = randomizedEigen(200, apply, {6, 4, q, 11});
    return subspaceSine(s.U.leftCols(6), r.vectors);
  };
  const double coarse = error(0), fine = error(6);
  INFO("sin(angle): q = 0 " << coarse << ", q = 6 " << fine);
  CHECK(coarse > 1e-4);
  CHECK(fine < 1e-6);
  CHECK(fine < 1e-3 * coarse);
}

TEST_CASE("randomized eigensolver is deterministic for a seed and handles rank-deficient operators", "[random][eigen]") {
  // Rank 3 operator asked for 5 modes: two eigenvalues are zero, and the vectors stay orthonormal.
  const Eigen::MatrixXd U = randomOrthogonal(50, 5).leftCols(3);
  const Eigen::MatrixXd A = U * Eigen::Vector3d(3.0, 2.0, 1.0).asDiagonal() * U.transpose();
  const BlockProduct apply = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& AX) { AX = A * X; };
  const EigenPairs a = randomizedEigen(50, apply, {5, 5, 1, 42});
  const EigenPairs b = randomizedEigen(50, apply, {5, 5, 1, 42});
  CHECK(a.values == b.values);
  CHECK(a.vectors == b.vectors);
  CHECK(a.values[0] == Approx(3.0).epsilon(1e-12));
  CHECK(a.values[2] == Approx(1.0).epsilon(1e-12));
  CHECK(std::abs(a.values[3]) < 1e-12);
  CHECK(std::abs(a.values[4]) < 1e-12);
  CHECK((a.vectors.transpose() * a.vectors - Eigen::MatrixXd::Identity(5, 5)).norm() < 1e-12);
  const EigenPairs other = randomizedEigen(50, apply, {5, 5, 1, 43});
  CHECK((other.vectors.leftCols(3) - a.vectors.leftCols(3)).cwiseAbs().maxCoeff() < 1e-10);  // signs fixed
}

TEST_CASE("randomized eigensolver rejects bad options and bad products", "[random][eigen]") {
  const BlockProduct identity = [](const Eigen::MatrixXd& X, Eigen::MatrixXd& AX) { AX = X; };
  CHECK_THROWS_AS(randomizedEigen(10, identity, {0, 5, 1, 1}), InvalidInput);
  CHECK_THROWS_AS(randomizedEigen(10, identity, {11, 5, 1, 1}), InvalidInput);
  CHECK_THROWS_AS(randomizedEigen(10, BlockProduct{}, {2, 5, 1, 1}), InvalidInput);
  const BlockProduct wrongShape = [](const Eigen::MatrixXd& X, Eigen::MatrixXd& AX) { AX = X.leftCols(1); };
  CHECK_THROWS_AS(randomizedEigen(10, wrongShape, {2, 2, 1, 1}), SolverFailure);
  const BlockProduct nan = [](const Eigen::MatrixXd& X, Eigen::MatrixXd& AX) {
    AX = X;
    AX(0, 0) = std::nan("");
  };
  CHECK_THROWS_AS(randomizedEigen(10, nan, {2, 2, 1, 1}), SolverFailure);
  // l = k + p larger than n is capped at n: the whole space, exact.
  const EigenPairs all = randomizedEigen(10, identity, {10, 5, 0, 1});
  CHECK((all.values.array() - 1.0).abs().maxCoeff() < 1e-14);
}
