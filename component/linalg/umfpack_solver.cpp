// UMFPACK through its 64-bit C interface. The CSR arrays of A are the CSC arrays of A^T, so we
// factorize A^T and solve with UMFPACK_At: no copy or transpose of the matrix.
#include <umfpack.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <mutex>
#include <string>

#include "core/errors.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/metis_ordering.hpp"

namespace peristep {
namespace {

class UmfpackSolver final : public LinearSolver {
 public:
  explicit UmfpackSolver(bool metis) : metis_(metis) {
    umfpack_dl_defaults(control_);
    if (metis_) control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  }
  ~UmfpackSolver() override { release(); }
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;


  void analyze(const CsrMatrix& A) override {
    release();
    std::unique_lock lock(metisMutex(), std::defer_lock);  // UMFPACK calls METIS
    if (metis_) lock.lock();
    check(umfpack_dl_symbolic(A.rows, A.cols, A.rowStart.data(), A.col.data(), A.value.data(), &symbolic_,
                              control_, info_),
          "symbolic analysis");
  }

  void factorize(const CsrMatrix& A) override {
    if (!symbolic_) analyze(A);
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    A_ = &A;
    check(umfpack_dl_numeric(A.rowStart.data(), A.col.data(), A.value.data(), symbolic_, &numeric_, control_, info_),
          "numeric factorization");
  }

  void solve(std::span<const double> b, std::span<double> x) override { solveWith(b, x, control_); }

  void precondition(std::span<const double> b, std::span<double> x) override {
    double control[UMFPACK_CONTROL];
    std::copy(std::begin(control_), std::end(control_), control);
    control[UMFPACK_IRSTEP] = 0;  // GMRES refines; UMFPACK's own refinement would triple the cost
    solveWith(b, x, control);
  }

 private:
  void solveWith(std::span<const double> b, std::span<double> x, const double* control) {
    if (!numeric_) throw SolverFailure("umfpack: solve called before factorize");
    check(umfpack_dl_solve(UMFPACK_At, A_->rowStart.data(), A_->col.data(), A_->value.data(), x.data(), b.data(),
                           numeric_, control, info_),
          "solve");
    for (double v : x)
      if (!std::isfinite(v)) throw SolverFailure("umfpack: solution is not finite (singular system?)");
  }

  void check(long status, const char* what) const {
    // UMFPACK_WARNING_singular_matrix still produces a factorization; a singular system is
    // reported by the NaN check of the solution instead.
    if (status == UMFPACK_OK || status == UMFPACK_WARNING_singular_matrix) return;
    throw SolverFailure("umfpack: " + std::string(what) + " failed with status " + std::to_string(status));
  }
  void release() {
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
  }

  bool metis_;
  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  const CsrMatrix* A_ = nullptr;
};

}  // namespace

std::unique_ptr<LinearSolver> makeUmfpackSolver(bool metisOrdering) {
  return std::make_unique<UmfpackSolver>(metisOrdering);
}

}  // namespace peristep
