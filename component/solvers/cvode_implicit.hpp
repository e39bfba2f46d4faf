#pragma once
// SUNDIALS CVODE BDF on y = (u, v, W): Newton iteration with matrix-free SPGMR (exact Jacobian-vector
// products from the model's linearization) left-preconditioned by TangentPreconditioner.
#include <memory>

#include "solvers/time_integrator.hpp"

namespace peristep {

std::unique_ptr<TimeIntegrator> makeCvodeImplicit(DynamicProblem& problem, const IntegratorOptions& options);

}  // namespace peristep
