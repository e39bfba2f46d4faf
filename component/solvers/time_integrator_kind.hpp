#pragma once
// Which time integrator a dynamic run uses (solvers/time_integrator.hpp), carried as this one value from
// the FMI variable timeIntegrator to the factory.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/option_table.hpp"

namespace peristep {

enum class TimeIntegratorKind { CentralDifference, ArkodeErk, CvodeBdf };

// Every time integrator, its name and description (the FMI enumeration PeriStep.TimeIntegrator lists these).
inline constexpr std::array<Option<TimeIntegratorKind>, 3> kTimeIntegratorOptions{{
    {TimeIntegratorKind::CentralDifference, "centralDifference",
     "Explicit central difference 001:(35)-(36), fixed step internalTimeStep"},
    {TimeIntegratorKind::ArkodeErk, "arkodeErk", "SUNDIALS ARKODE explicit adaptive Runge-Kutta"},
    {TimeIntegratorKind::CvodeBdf, "cvodeBdf", "SUNDIALS CVODE BDF with a preconditioned Krylov solver (stiff)"},
}};

inline std::vector<std::string> timeIntegratorNames() { return optionNames(kTimeIntegratorOptions); }

// The integrator a name stands for (command lines of the benches and tests); throws InvalidInput for an
// unknown name, listing the known ones.
inline TimeIntegratorKind timeIntegratorKind(std::string_view name) {
  return optionKind(kTimeIntegratorOptions, name, "time integrator");
}

}  // namespace peristep
