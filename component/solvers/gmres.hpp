#pragma once
// Restarted GMRES, right-preconditioned by a LinearSolver: used to reuse a factorization of a nearby
// matrix (a few bonds broken since it was computed) instead of refactorizing.
#include <functional>
#include <span>

#include "core/csr_matrix.hpp"
#include "solvers/linear_solver.hpp"

namespace peristep {

struct GmresResult {
  bool converged = false;
  int iterations = 0;
  double relativeResidual = 0;
};

// Solves A x = b starting from x; stops at ||b - A x|| <= tol ||b|| or after maxIterations.
GmresResult gmres(const CsrMatrix& A, LinearSolver& preconditioner, std::span<const double> b, std::span<double> x,
                  double tol, int maxIterations, int restart = 30);

// The same with the operator and the preconditioner as functions out = f(in).
using VectorMap = std::function<void(std::span<const double>, std::span<double>)>;
GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, std::span<const double> b,
                  std::span<double> x, double tol, int maxIterations, int restart = 30);

}  // namespace peristep
