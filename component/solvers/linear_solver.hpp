#pragma once
// One small interface for the sparse solvers, so that drivers can swap them and reuse factorizations.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/csr_matrix.hpp"

namespace peristep {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
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

// "umfpack" (UMFPACK, 64-bit indices, METIS nested-dissection ordering: the fastest here, see
// bench/README.md), "umfpack-amd" (UMFPACK with its default AMD/COLAMD ordering),
// "sparselu" (Eigen SparseLU, COLAMD), "bicgstab-ilut" (Eigen BiCGSTAB with an ILUT preconditioner).
std::unique_ptr<LinearSolver> makeLinearSolver(const std::string& name);
const std::vector<std::string>& linearSolverNames();

std::unique_ptr<LinearSolver> makeUmfpackSolver(bool metisOrdering);
std::unique_ptr<LinearSolver> makeSparseLuSolver();
std::unique_ptr<LinearSolver> makeBicgstabIlutSolver();

}  // namespace peristep
