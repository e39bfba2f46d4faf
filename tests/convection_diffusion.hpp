#pragma once
// A nonsymmetric sparse test matrix (a 2D five-point stencil on an m x m grid with a skew convection term), and
// any CSR matrix as a dense one.
#include <Eigen/Dense>

#include "core/csr_matrix.hpp"

inline peristep::CsrMatrix convectionDiffusion(int m) {
  peristep::CsrMatrix A;
  A.rows = A.cols = m * m;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int r = i * m + j;
      const auto add = [&](int c, double v) {
        A.col.push_back(c);
        A.value.push_back(v);
      };
      if (i > 0) add(r - m, -1.0 - 0.3);
      if (j > 0) add(r - 1, -1.0 + 0.2);
      add(r, 4.5);
      if (j < m - 1) add(r + 1, -1.0 - 0.2);
      if (i < m - 1) add(r + m, -1.0 + 0.3);
      A.rowStart.push_back(static_cast<std::int64_t>(A.col.size()));
    }
  return A;
}

inline Eigen::MatrixXd dense(const peristep::CsrMatrix& A) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(A.rows, A.cols);
  for (std::int64_t r = 0; r < A.rows; ++r)
    for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k) D(r, A.col[k]) = A.value[k];
  return D;
}
