#pragma once
// Which sparse solver a quasi-static scene uses (linalg/linear_solver.hpp), carried as this one value from
// the FMI variable linearSolver to the factory.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/option_table.hpp"

namespace peristep {

enum class LinearSolverKind { Umfpack, UmfpackAmd, SparseLu, BicgstabIlut };

// Every linear solver, its name and description (the FMI enumeration PeriStep.LinearSolver lists these).
// Umfpack is the fastest here, see docs/decisions/0013-umfpack-metis-default-solver.md.
inline constexpr std::array<Option<LinearSolverKind>, 4> kLinearSolverOptions{{
    {LinearSolverKind::Umfpack, "umfpack", "UMFPACK, 64-bit indices, METIS ordering"},
    {LinearSolverKind::UmfpackAmd, "umfpackAmd", "UMFPACK with its default AMD/COLAMD ordering"},
    {LinearSolverKind::SparseLu, "sparseLU", "Eigen SparseLU"},
    {LinearSolverKind::BicgstabIlut, "bicgstabIlut", "Eigen BiCGSTAB with an ILUT preconditioner"},
}};

inline std::vector<std::string> linearSolverNames() { return optionNames(kLinearSolverOptions); }

// The solver a name stands for (command lines of the benches and tests); throws InvalidInput for an
// unknown name, listing the known ones.
inline LinearSolverKind linearSolverKind(std::string_view name) {
  return optionKind(kLinearSolverOptions, name, "linear solver");
}

}  // namespace peristep
