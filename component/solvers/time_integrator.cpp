#include "solvers/time_integrator.hpp"

#include "core/errors.hpp"
#include "solvers/arkode_explicit.hpp"
#include "solvers/central_difference.hpp"
#include "solvers/cvode_implicit.hpp"

namespace peristep {

std::unique_ptr<TimeIntegrator> makeTimeIntegrator(TimeIntegratorKind kind, DynamicProblem& problem,
                                                   const IntegratorOptions& options) {
  switch (kind) {
    case TimeIntegratorKind::CentralDifference: return std::make_unique<CentralDifference>(problem, options);
    case TimeIntegratorKind::ArkodeErk: return makeArkodeExplicit(problem, options);
    case TimeIntegratorKind::CvodeBdf: return makeCvodeImplicit(problem, options);
  }
  throw InvalidInput("unknown time integrator " + std::to_string(static_cast<int>(kind)));
}

std::unique_ptr<TimeIntegrator> makeTimeIntegrator(std::string_view name, DynamicProblem& problem,
                                                   const IntegratorOptions& options) {
  return makeTimeIntegrator(timeIntegratorKind(name), problem, options);
}

}  // namespace peristep
