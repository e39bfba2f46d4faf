#pragma once
// Sums over many rows that do not depend on the number of threads: the rows go in fixed blocks, one
// thread sums a block, and the blocks' partial sums are added in block order. A result is then the
// same bits on one thread or two, in a restored checkpoint, and under mpirun (one thread per rank).
#include <algorithm>
#include <cstddef>
#include <vector>

namespace peristep {

inline constexpr std::size_t kSumBlock = 4096;

// The sums over rows i < n of addRow(i, partial), `width` values each.
template <class F>
std::vector<double> blockedSums(std::size_t n, std::size_t width, F&& addRow, bool threaded = true) {
  const std::size_t blocks = (n + kSumBlock - 1) / kSumBlock;
  std::vector<double> partial(blocks * width, 0.0);
#pragma omp parallel for schedule(static) if (threaded)
  for (std::size_t blk = 0; blk < blocks; ++blk)
    for (std::size_t i = blk * kSumBlock; i < std::min(n, (blk + 1) * kSumBlock); ++i) addRow(i, &partial[blk * width]);
  std::vector<double> sum(width, 0.0);
  for (std::size_t blk = 0; blk < blocks; ++blk)
    for (std::size_t a = 0; a < width; ++a) sum[a] += partial[blk * width + a];
  return sum;
}

// The sum over rows i < n of term(i); term may also update row i (each row is visited once).
template <class F>
double blockedSum(std::size_t n, F&& term, bool threaded = true) {
  return blockedSums(n, 1, [&](std::size_t i, double* partial) { *partial += term(i); }, threaded)[0];
}

}  // namespace peristep
