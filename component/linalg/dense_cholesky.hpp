#pragma once
// Dense Cholesky factor A = L L^T of the lower triangle of a symmetric positive definite matrix, in
// float or double, for the 002 bar's tangent (a few hundred unknowns, factored some 140 times per
// realization). Eigen's LLT is compiled for the baseline SSE2 only, and OpenBLAS's ?potrf, twice as fast
// on one thread, starts its own threads inside the OpenMP loop over realizations (3.5x slower there)
// and rounds differently with their number. This one runs its column updates in AVX-512 / AVX2 clones,
// without fused multiply-adds: every clone and every thread count give the same factor.
// info() and solve() as Eigen::LLT's.
#include <Eigen/Dense>

namespace peristep {

template <typename Scalar>
class DenseCholesky {
 public:
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

  // Factors the lower triangle of A (converted to Scalar); the upper triangle is not read.
  void compute(const Eigen::MatrixXd& A);
  Eigen::ComputationInfo info() const { return ok_ ? Eigen::Success : Eigen::NumericalIssue; }
  Vector solve(Vector b) const {
    factor_.template triangularView<Eigen::Lower>().solveInPlace(b);
    factor_.template triangularView<Eigen::Lower>().adjoint().solveInPlace(b);
    return b;
  }
  const Matrix& matrixL() const { return factor_; }  // lower triangle

 private:
  Matrix factor_;
  bool ok_ = false;
};

extern template class DenseCholesky<float>;
extern template class DenseCholesky<double>;

}  // namespace peristep
