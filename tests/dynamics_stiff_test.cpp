#include <catch2/catch.hpp>

#include <cmath>

#include "scenes/stiff_inclusions.hpp"
#include "solvers/central_difference.hpp"

using namespace peristep;

// DESIGN 7: stiff dynamics handled by the implicit SUNDIALS integrator. Plate with inclusions 1e3
// times stiffer than the matrix (component/scenes/stiff_inclusions.hpp), 40 us of a smoothly ramped
// load. The explicit reference is central difference at half its stability limit (its own error,
// estimated against a quarter of the limit, is ~4e-8). Stated tolerance: relative L2 error of the
// final displacement below 1e-3.
TEST_CASE("stiff inclusions (contrast 1e3): CVODE BDF reaches the explicit reference with fewer force evaluations",
          "[dynamics]") {
  StiffInclusionsSpec spec;
  spec.contrast = 1e3;
  DynamicScene reference = makeStiffInclusions(spec);
  const StabilityEstimate limit = estimateStabilityLimit(*reference.problem);
  IntegratorOptions explicitOptions;
  explicitOptions.timeStep = 0.5 * limit.criticalStep;
  CentralDifference cd(*reference.problem, explicitOptions);
  cd.advanceTo(spec.endTime);
  const std::vector<double> uRef(cd.displacement(), cd.displacement() + reference.problem->dofs());

  DynamicScene scene = makeStiffInclusions(spec);
  IntegratorOptions o;
  o.relativeTolerance = 1e-5;
  o.absoluteTolerance = 1e-11;  // displacements ~1e-6 m
  o.velocityTolerance = 1e-6;   // velocities ~0.1 m/s
  auto bdf = makeTimeIntegrator("cvodeBdf", *scene.problem, o);
  bdf->advanceTo(spec.endTime);
  double d = 0, n = 0;
  for (std::size_t i = 0; i < uRef.size(); ++i) {
    d += (bdf->displacement()[i] - uRef[i]) * (bdf->displacement()[i] - uRef[i]);
    n += uRef[i] * uRef[i];
  }
  const double error = std::sqrt(d / n);
  const IntegratorStats s = bdf->stats();
  // No explicit scheme can take fewer force evaluations than central difference at its limit.
  const double explicitMinimum = std::ceil(spec.endTime / limit.criticalStep);
  INFO("BDF: " << s.steps << " steps, " << s.rhsEvaluations << " f + " << s.jacobianProducts << " J v, "
               << s.seconds << " s; central difference: >= " << explicitMinimum << " steps, reference "
               << cd.stats().steps << " steps in " << cd.stats().seconds << " s; relative error " << error);
  CHECK(error < 1e-3);
  CHECK(static_cast<double>(s.forceEquivalents()) < 0.5 * explicitMinimum);
}
