#pragma once
// SUNDIALS ARKODE ERKStep (explicit adaptive Runge-Kutta, default 4th-order table with embedded
// error estimate) on the first-order form y = (u, v, W) of the semi-discrete system.
#include <memory>

#include "solvers/time_integrator.hpp"

namespace peristep {

std::unique_ptr<TimeIntegrator> makeArkodeExplicit(DynamicProblem& problem, const IntegratorOptions& options);

}  // namespace peristep
