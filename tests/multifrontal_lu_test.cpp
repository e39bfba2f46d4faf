// The project's multifrontal LU (single precision, no pivoting) against dense double solves: a plain solve, the
// Schur complement with condensation and expansion on a grid large enough for BLAS fronts, relaxed
// supernodes and both substitution groups, results independent of the thread count, and a zero pivot refused.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <omp.h>
#include <vector>

#include "core/errors.hpp"
#include "linalg/metis_ordering.hpp"
#include "linalg/multifrontal_lu.hpp"

#include "convection_diffusion.hpp"

using namespace peristep;

namespace {

// Nested dissection of the rest, then the zone.
std::vector<std::int32_t> zoneLast(const CsrMatrix& A, const std::vector<std::int64_t>& zone) {
  const auto n = static_cast<std::size_t>(A.rows);
  std::vector<bool> inZone(n, false);
  for (std::int64_t u : zone) inZone[static_cast<std::size_t>(u)] = true;
  std::vector<std::int32_t> rest, index(n, -1);
  for (std::size_t u = 0; u < n; ++u)
    if (!inZone[u]) {
      index[u] = static_cast<std::int32_t>(rest.size());
      rest.push_back(static_cast<std::int32_t>(u));
    }
  std::vector<std::int32_t> xadj{0}, adjacency;
  for (std::int32_t u : rest) {
    for (std::int64_t k = A.rowStart[static_cast<std::size_t>(u)]; k < A.rowStart[static_cast<std::size_t>(u) + 1]; ++k) {
      const auto c = static_cast<std::size_t>(A.col[static_cast<std::size_t>(k)]);
      if (c != static_cast<std::size_t>(u) && !inZone[c]) adjacency.push_back(index[c]);
    }
    xadj.push_back(static_cast<std::int32_t>(adjacency.size()));
  }
  const std::vector<std::int32_t> order = nestedDissection(xadj, adjacency);
  std::vector<std::int32_t> position(n);
  for (std::size_t k = 0; k < rest.size(); ++k) position[static_cast<std::size_t>(rest[k])] = order[k];
  for (std::size_t t = 0; t < zone.size(); ++t) position[static_cast<std::size_t>(zone[t])] = static_cast<std::int32_t>(rest.size() + t);
  return position;
}

Eigen::VectorXd rightHandSide(std::int64_t n) {
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b(i) = std::sin(0.7 * static_cast<double>(i)) + 0.1;
  return b;
}

}  // namespace

TEST_CASE("multifrontal LU: a plain solve to single precision", "[solver][multifrontal]") {
  const CsrMatrix A = convectionDiffusion(30);
  const std::vector<double> scale(static_cast<std::size_t>(A.rows), 0.5);  // solves D A D
  MultifrontalLu lu;
  lu.analyze(A, zoneLast(A, {}), 0, {});
  std::vector<double> schur;
  lu.factorize(A, scale, schur);
  CHECK(schur.empty());
  const Eigen::VectorXd b = rightHandSide(A.rows);
  std::vector<double> x(static_cast<std::size_t>(A.rows));
  lu.solve(std::span<const double>(b.data(), static_cast<std::size_t>(b.size())), x);
  const Eigen::VectorXd exact = (0.25 * dense(A)).lu().solve(b);
  const double error = (Eigen::Map<const Eigen::VectorXd>(x.data(), A.rows) - exact).norm() / exact.norm();
  CHECK(error <= 1e-5);
  CHECK(error > 1e-12);  // single-precision factors
  // Fill-reducing order: far fewer entries than the dense 900 x 900.
  CHECK(lu.factorEntries() < A.rows * A.rows / 10);
}

TEST_CASE("multifrontal LU: the Schur complement, condensation and expansion on a 70 x 70 grid, the same with one "
          "thread or two",
          "[solver][multifrontal]") {
  const int m = 70;
  const CsrMatrix A = convectionDiffusion(m);
  std::vector<std::int64_t> zone;  // a block in the middle of the grid
  for (int i = 30; i < 38; ++i)
    for (int j = 20; j < 45; ++j) zone.push_back(i * m + j);
  const std::vector<double> unscaled(static_cast<std::size_t>(A.rows), 1.0);
  MultifrontalLu lu;
  lu.analyze(A, zoneLast(A, zone), zone.size(), zone);
  std::vector<double> schur;
  lu.factorize(A, unscaled, schur);

  const Eigen::MatrixXd D = dense(A);
  std::vector<int> rest, zoneIndex(zone.begin(), zone.end());
  for (int i = 0; i < A.rows; ++i)
    if (std::find(zone.begin(), zone.end(), i) == zone.end()) rest.push_back(i);
  const Eigen::MatrixXd expected = D(zoneIndex, zoneIndex) - D(zoneIndex, rest) * D(rest, rest).lu().solve(D(rest, zoneIndex));
  const auto z = static_cast<Eigen::Index>(zone.size());
  const Eigen::Map<const Eigen::MatrixXd> S(schur.data(), z, z);
  CHECK((S - expected).norm() <= 1e-5 * expected.norm());

  const Eigen::VectorXd b = rightHandSide(A.rows);
  const std::span<const double> bSpan(b.data(), static_cast<std::size_t>(b.size()));
  auto solveWith = [&](int threads) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    std::vector<double> reduced(zone.size()), xz(zone.size()), x(static_cast<std::size_t>(A.rows));
    lu.condense(bSpan, reduced);
    Eigen::Map<Eigen::VectorXd>(xz.data(), z) = S.lu().solve(Eigen::Map<const Eigen::VectorXd>(reduced.data(), z));
    lu.expand(xz, x);
    omp_set_num_threads(saved);
    return x;
  };
  const std::vector<double> x = solveWith(2);
  const Eigen::VectorXd exact = D.lu().solve(b);
  CHECK((Eigen::Map<const Eigen::VectorXd>(x.data(), A.rows) - exact).norm() <= 1e-5 * exact.norm());
  CHECK(solveWith(1) == x);  // the groups' sums enter in a fixed order
}

TEST_CASE("multifrontal LU: a zero pivot is refused, not divided by", "[solver][multifrontal]") {
  // [[0, 1], [1, 0]] needs a row exchange, which this LU does not make.
  CsrMatrix A;
  A.rows = A.cols = 2;
  A.rowStart = {0, 2, 4};
  A.col = {0, 1, 0, 1};
  A.value = {0.0, 1.0, 1.0, 0.0};
  MultifrontalLu lu;
  lu.analyze(A, {0, 1}, 0, {});
  std::vector<double> schur;
  const std::vector<double> unscaled{1.0, 1.0};
  CHECK_THROWS_AS(lu.factorize(A, unscaled, schur), SolverFailure);
}
