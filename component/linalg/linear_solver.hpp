#pragma once
// One small interface for the sparse solvers, so that drivers can swap them and reuse factorizations.
#include <memory>
#include <span>

#include "core/csr_matrix.hpp"
#include "linalg/linear_solver_kind.hpp"

namespace peristep {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Symbolic analysis (ordering, pattern). Call again only when the sparsity pattern changes.
  virtual void analyze(const CsrMatrix& A) = 0;
  // Numeric factorization or preconditioner of A, which has the analyzed pattern. A must stay
  // alive and unchanged until the next factorize().
  virtual void factorize(const CsrMatrix& A) = 0;
  // x = A^{-1} b; throws SolverFailure when it cannot deliver a finite solution.
  virtual void solve(std::span<const double> b, std::span<double> x) = 0;
  // x ~ A^{-1} b as a preconditioner inside a Krylov method: may skip what only polishes the answer
  // (UMFPACK's iterative refinement, which costs three times the triangular solves themselves).
  virtual void precondition(std::span<const double> b, std::span<double> x) { solve(b, x); }
};

std::unique_ptr<LinearSolver> makeLinearSolver(LinearSolverKind kind);

std::unique_ptr<LinearSolver> makeUmfpackSolver(bool metisOrdering);
std::unique_ptr<LinearSolver> makeSparseLuSolver();
std::unique_ptr<LinearSolver> makeBicgstabIlutSolver();

}  // namespace peristep
