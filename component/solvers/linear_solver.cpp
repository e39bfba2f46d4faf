#include "solvers/linear_solver.hpp"

#include "core/errors.hpp"

namespace peristep {

const std::vector<std::string>& linearSolverNames() {
  static const std::vector<std::string> names{"umfpack", "umfpack-amd", "sparselu", "bicgstab-ilut"};
  return names;
}

std::unique_ptr<LinearSolver> makeLinearSolver(const std::string& name) {
  if (name == "umfpack") return makeUmfpackSolver(true);
  if (name == "umfpack-amd") return makeUmfpackSolver(false);
  if (name == "sparselu") return makeSparseLuSolver();
  if (name == "bicgstab-ilut") return makeBicgstabIlutSolver();
  std::string known;
  for (const auto& n : linearSolverNames()) known += (known.empty() ? "" : ", ") + n;
  throw InvalidInput("unknown linear solver '" + name + "' (known: " + known + ")");
}

}  // namespace peristep
