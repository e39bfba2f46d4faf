#include "linalg/linear_solver.hpp"

#include "core/errors.hpp"

namespace peristep {

std::unique_ptr<LinearSolver> makeLinearSolver(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::Umfpack: return makeUmfpackSolver(true);
    case LinearSolverKind::UmfpackAmd: return makeUmfpackSolver(false);
    case LinearSolverKind::SparseLu: return makeSparseLuSolver();
    case LinearSolverKind::BicgstabIlut: return makeBicgstabIlutSolver();
  }
  throw InvalidInput("unknown linear solver " + std::to_string(static_cast<int>(kind)));
}

}  // namespace peristep
