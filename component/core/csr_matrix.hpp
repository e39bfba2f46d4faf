#pragma once
// Compressed sparse row matrix with 64-bit indices (UMFPACK's umfpack_dl takes them directly).
#include <cstdint>
#include <span>
#include <vector>

namespace peristep {

struct CsrMatrix {
  std::int64_t rows = 0, cols = 0;
  std::vector<std::int64_t> rowStart{0};  // size rows + 1
  std::vector<std::int64_t> col;          // ascending within each row
  std::vector<double> value;

  std::int64_t nonZeros() const { return rowStart.back(); }

  // y = A x
  void multiply(std::span<const double> x, std::span<double> y) const {
#pragma omp parallel for schedule(static)
    for (std::int64_t r = 0; r < rows; ++r) {
      double s = 0.0;
      for (std::int64_t k = rowStart[r]; k < rowStart[r + 1]; ++k) s += value[k] * x[col[k]];
      y[r] = s;
    }
  }
};

}  // namespace peristep
