// GMRES with recycled directions against plain GMRES on a sequence of matrices that change in a few rows, with
// the factors of the first matrix as the preconditioner (the situation of the crack-zone driver).
#include <catch2/catch.hpp>
#include <omp.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "convection_diffusion.hpp"
#include "core/memory.hpp"
#include "linalg/gmres.hpp"

using namespace peristep;

namespace {

// Weakens the couplings of rows first..first+count (a "broken" stretch of a line through the grid).
std::vector<std::size_t> weakenRows(CsrMatrix& A, std::size_t first, std::size_t count) {
  std::vector<std::size_t> rows;
  for (std::size_t r = first; r < first + count; ++r) {
    for (auto k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k)
      A.value[k] *= static_cast<std::size_t>(A.col[k]) == r ? 0.6 : 0.1;
    rows.push_back(r);
  }
  return rows;
}

struct Sequence {
  std::vector<std::vector<double>> solutions;
  std::vector<int> iterations;
  std::vector<double> trueResiduals;
};

// Five systems: each weakens six more rows; every solve from x = 0 with the factors of the first matrix.
Sequence solveSequence(bool recycle) {
  CsrMatrix A = convectionDiffusion(24);
  const auto n = static_cast<std::size_t>(A.rows);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(dense(A));
  const VectorMap precondition = [&](std::span<const double> in, std::span<double> out) {
    const Eigen::VectorXd y = lu.solve(Eigen::Map<const Eigen::VectorXd>(in.data(), A.rows));
    std::copy(y.data(), y.data() + A.rows, out.begin());
  };
  const VectorMap apply = [&](std::span<const double> in, std::span<double> out) { A.multiply(in, out); };
  std::vector<double> b(n), ones(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.5;
  RecycledDirections kept(60);
  Sequence s;
  for (int step = 0; step < 5; ++step) {
    for (std::size_t r : weakenRows(A, 12 * 24 + 3 + 6 * static_cast<std::size_t>(step), 6))
      kept.refreshRow(r, std::span(A.col).subspan(A.rowStart[r], A.rowStart[r + 1] - A.rowStart[r]),
                      std::span(A.value).subspan(A.rowStart[r], A.rowStart[r + 1] - A.rowStart[r]), ones);
    std::vector<double> x(n, 0.0), Ax(n);
    const GmresResult result = gmres(apply, precondition, b, x, 1e-12, 200, 40, recycle ? &kept : nullptr);
    REQUIRE(result.converged);
    A.multiply(x, Ax);
    double r2 = 0, b2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      r2 += (b[i] - Ax[i]) * (b[i] - Ax[i]);
      b2 += b[i] * b[i];
    }
    s.solutions.push_back(x);
    s.iterations.push_back(result.iterations);
    s.trueResiduals.push_back(std::sqrt(r2 / b2));
  }
  return s;
}

}  // namespace

TEST_CASE("recycled GMRES: the kept directions cut the iterations of later systems, and A Z stays exact",
          "[solver][gmres]") {
  const Sequence plain = solveSequence(false), recycled = solveSequence(true);
  for (std::size_t t = 0; t < plain.iterations.size(); ++t) {
    INFO("system " << t << ": plain " << plain.iterations[t] << ", recycled " << recycled.iterations[t]);
    // Each converges to the true residual (the refreshed rows keep C = A Z for the changed matrix).
    CHECK(recycled.trueResiduals[t] <= 1e-11);
    CHECK(plain.trueResiduals[t] <= 1e-11);
    // Plain GMRES searches again for every change since the factors (7, 13, 17, 19, 21 iterations); with the
    // kept directions a system costs what its own six new rows cost.
    if (t > 0) CHECK(recycled.iterations[t] < plain.iterations[t]);
    CHECK(recycled.iterations[t] <= plain.iterations.front());
  }
  CHECK(recycled.iterations.front() == plain.iterations.front());  // nothing kept yet: GMRES as before
}

TEST_CASE("recycled GMRES gives the same bits with one thread and with two", "[solver][gmres]") {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Sequence one = solveSequence(true);
  omp_set_num_threads(2);
  const Sequence two = solveSequence(true);
  omp_set_num_threads(threads);
  CHECK(one.iterations == two.iterations);
  CHECK(one.solutions == two.solutions);
}

TEST_CASE("a GMRES solve that converges in a few iterations holds only their Krylov vectors in memory",
          "[solver][gmres]") {
  // A diagonal system with a preconditioner off by up to 4e-9 in five clusters: a few iterations reach 1e-13. A
  // restart of 40 allocated up front would hold 81 vectors (650 MB at this size); the solve holds what it reached.
  const std::size_t n = 1'000'000;
  std::vector<double> b(n), x(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) b[i] = 1.0 + 1e-6 * static_cast<double>(i % 97);
  const auto diagonal = [](std::size_t i) { return 2.0 + static_cast<double>(i % 13); };
  const VectorMap apply = [&](std::span<const double> in, std::span<double> out) {
    for (std::size_t i = 0; i < n; ++i) out[i] = diagonal(i) * in[i];
  };
  const VectorMap precondition = [&](std::span<const double> in, std::span<double> out) {
    for (std::size_t i = 0; i < n; ++i) out[i] = in[i] / diagonal(i) * (1.0 + 1e-9 * static_cast<double>(i % 5));
  };
  REQUIRE(resetPeakMemory());
  const std::size_t before = peakMemoryBytes();
  const GmresResult result = gmres(apply, precondition, b, x, 1e-13, 200, 40);
  const double grownVectors = static_cast<double>(peakMemoryBytes() - before) / (8.0 * static_cast<double>(n));
  INFO("iterations " << result.iterations << ", peak grew by " << grownVectors << " vectors");
  REQUIRE(result.converged);
  REQUIRE(result.iterations <= 5);
  // V and Z of the iterations reached (j + 1 and j), w and r
  CHECK(grownVectors < 2.0 * result.iterations + 3.5);
}
