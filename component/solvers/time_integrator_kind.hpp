#pragma once
// Which time integrator a dynamic run uses (solvers/time_integrator.hpp), carried as this one value from
// the FMI variable to the factory.
namespace peristep {

enum class TimeIntegratorKind { CentralDifference, ArkodeErk, CvodeBdf };

}  // namespace peristep
