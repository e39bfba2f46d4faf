// Eigen's sparse LU and BiCGSTAB + ILUT, kept for comparison with UMFPACK (see bench/).
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cmath>

#include "core/errors.hpp"
#include "linalg/linear_solver.hpp"

namespace peristep {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, std::int64_t>;

RowMatrix toEigen(const CsrMatrix& A) {
  return Eigen::Map<const RowMatrix>(A.rows, A.cols, A.nonZeros(), A.rowStart.data(), A.col.data(), A.value.data());
}

void checkFinite(std::span<const double> x, const char* who) {
  for (double v : x)
    if (!std::isfinite(v)) throw SolverFailure(std::string(who) + ": solution is not finite");
}

class SparseLuSolver final : public LinearSolver {
 public:
  void analyze(const CsrMatrix& A) override { lu_.analyzePattern(Eigen::SparseMatrix<double>(toEigen(A))); }
  void factorize(const CsrMatrix& A) override {
    lu_.factorize(Eigen::SparseMatrix<double>(toEigen(A)));
    if (lu_.info() != Eigen::Success) throw SolverFailure("sparseLU: factorization failed: " + lu_.lastErrorMessage());
  }
  void solve(std::span<const double> b, std::span<double> x) override {
    Eigen::Map<const Eigen::VectorXd> bv(b.data(), static_cast<Eigen::Index>(b.size()));
    Eigen::Map<Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size())) = lu_.solve(bv);
    checkFinite(x, "sparseLU");
  }

 private:
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
};

class BicgstabIlutSolver final : public LinearSolver {
 public:
  void analyze(const CsrMatrix&) override {}
  void factorize(const CsrMatrix& A) override {
    A_ = toEigen(A);
    solver_.setTolerance(1e-12);
    solver_.setMaxIterations(5000);
    solver_.preconditioner().setDroptol(1e-4);
    solver_.preconditioner().setFillfactor(10);
    solver_.compute(A_);
    if (solver_.info() != Eigen::Success) throw SolverFailure("bicgstabIlut: preconditioner failed");
  }
  void solve(std::span<const double> b, std::span<double> x) override {
    Eigen::Map<const Eigen::VectorXd> bv(b.data(), static_cast<Eigen::Index>(b.size()));
    Eigen::Map<Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size())) = solver_.solve(bv);
    if (solver_.info() != Eigen::Success)
      throw SolverFailure("bicgstabIlut: no convergence after " + std::to_string(solver_.iterations()) +
                          " iterations (residual " + std::to_string(solver_.error()) + ")");
    checkFinite(x, "bicgstabIlut");
  }

 private:
  RowMatrix A_;
  Eigen::BiCGSTAB<RowMatrix, Eigen::IncompleteLUT<double, std::int64_t>> solver_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeSparseLuSolver() { return std::make_unique<SparseLuSolver>(); }
std::unique_ptr<LinearSolver> makeBicgstabIlutSolver() { return std::make_unique<BicgstabIlutSolver>(); }

}  // namespace peristep
