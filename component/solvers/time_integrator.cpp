#include "solvers/time_integrator.hpp"

#include "core/errors.hpp"
#include "solvers/arkode_explicit.hpp"
#include "solvers/central_difference.hpp"
#include "solvers/cvode_implicit.hpp"

namespace peristep {

std::vector<std::string> timeIntegratorNames() { return {"central_difference", "arkode_erk", "cvode_bdf"}; }

std::unique_ptr<TimeIntegrator> makeTimeIntegrator(std::string_view name, DynamicProblem& problem,
                                                   const IntegratorOptions& options) {
  if (name == "central_difference") return std::make_unique<CentralDifference>(problem, options);
  if (name == "arkode_erk") return makeArkodeExplicit(problem, options);
  if (name == "cvode_bdf") return makeCvodeImplicit(problem, options);
  std::string known;
  for (const std::string& n : timeIntegratorNames()) known += (known.empty() ? "" : ", ") + n;
  throw InvalidInput("unknown time integrator '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace peristep
