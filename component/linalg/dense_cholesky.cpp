#include "linalg/dense_cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "core/errors.hpp"

#define PERISTEP_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

namespace peristep {

namespace {

constexpr int kPanel = 8;  // columns factored together; each trailing column is then read and written once per panel

// y[i] -= sum_k l[k] x_k[i] for i < count: the update of one trailing column by a panel of kb columns.
// Plain loops over contiguous columns: GCC vectorizes them (restrict: the columns do not overlap).
template <typename T>
[[gnu::always_inline]] inline void columnUpdate(T* __restrict y, const T* __restrict x, int ld, const T* __restrict l, int kb,
                                                int count) {
  if (kb == kPanel) {
    const T l0 = l[0], l1 = l[1], l2 = l[2], l3 = l[3], l4 = l[4], l5 = l[5], l6 = l[6], l7 = l[7];
    const T *__restrict x0 = x, *__restrict x1 = x + ld, *__restrict x2 = x + 2 * ld, *__restrict x3 = x + 3 * ld;
    const T *__restrict x4 = x + 4 * ld, *__restrict x5 = x + 5 * ld, *__restrict x6 = x + 6 * ld, *__restrict x7 = x + 7 * ld;
    for (int i = 0; i < count; ++i)
      y[i] -= ((l0 * x0[i] + l1 * x1[i]) + (l2 * x2[i] + l3 * x3[i])) + ((l4 * x4[i] + l5 * x5[i]) + (l6 * x6[i] + l7 * x7[i]));
  } else {
    for (int k = 0; k < kb; ++k) {
      const T lk = l[k];
      const T* __restrict xk = x + static_cast<std::ptrdiff_t>(k) * ld;
      for (int i = 0; i < count; ++i) y[i] -= lk * xk[i];
    }
  }
}

// Right-looking Cholesky of the lower triangle of a (column-major, leading dimension n) by panels.
template <typename T>
[[gnu::always_inline]] inline bool factorLower(T* a, int n) {
  auto at = [&](int i, int j) -> T& { return a[static_cast<std::ptrdiff_t>(j) * n + i]; };
  T l[kPanel];
  for (int k0 = 0; k0 < n; k0 += kPanel) {
    const int kb = std::min(kPanel, n - k0);
    // The panel, column by column (its columns already carry the updates of the earlier panels).
    for (int k = k0; k < k0 + kb; ++k) {
      const T d = at(k, k);
      if (!(d > 0)) return false;
      const T root = std::sqrt(d);
      at(k, k) = root;
      for (int i = k + 1; i < n; ++i) at(i, k) /= root;
      for (int j = k + 1; j < k0 + kb; ++j) {
        const T lj = at(j, k);
        for (int i = j; i < n; ++i) at(i, j) -= lj * at(i, k);
      }
    }
    // The trailing columns: A(j:n, j) -= L(j:n, panel) L(j, panel)^T.
    for (int j = k0 + kb; j < n; ++j) {
      for (int k = 0; k < kb; ++k) l[k] = at(j, k0 + k);
      columnUpdate(&at(j, j), &at(j, k0), n, l, kb, n - j);
    }
  }
  return true;
}

PERISTEP_CLONES bool factorFloat(float* a, int n) { return factorLower(a, n); }
PERISTEP_CLONES bool factorDouble(double* a, int n) { return factorLower(a, n); }

}  // namespace

template <typename Scalar>
void DenseCholesky<Scalar>::compute(const Eigen::MatrixXd& A) {
  require(A.rows() == A.cols(), "Cholesky: the matrix must be square");
  factor_ = A.cast<Scalar>();
  const int n = static_cast<int>(factor_.rows());
  if constexpr (std::is_same_v<Scalar, float>)
    ok_ = factorFloat(factor_.data(), n);
  else
    ok_ = factorDouble(factor_.data(), n);
}

template class DenseCholesky<float>;
template class DenseCholesky<double>;

}  // namespace peristep
