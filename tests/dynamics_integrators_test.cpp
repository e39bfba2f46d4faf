#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "scenes/stiff_inclusions.hpp"
#include "solvers/central_difference.hpp"

using namespace peristep;

namespace {

double relativeL2(const double* u, const std::vector<double>& ref) {
  double d = 0, n = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    d += (u[i] - ref[i]) * (u[i] - ref[i]);
    n += ref[i] * ref[i];
  }
  return std::sqrt(d / n);
}

// A small soft plate (no inclusion contrast): every integrator can take it quickly.
StiffInclusionsSpec smallPlate() {
  StiffInclusionsSpec s;
  s.nx = 16;
  s.ny = 8;
  s.contrast = 1.0;
  s.rampTime = 2e-6;
  s.endTime = 3e-6;
  return s;
}

}  // namespace

TEST_CASE("integrators are chosen by name and unknown names are refused", "[dynamics]") {
  DynamicScene scene = makeStiffInclusions(smallPlate());
  IntegratorOptions o;
  o.timeStep = 1e-9;
  for (const std::string& name : timeIntegratorNames()) CHECK(makeTimeIntegrator(name, *scene.problem, o)->name() == name);
  try {
    makeTimeIntegrator("leapfrog", *scene.problem, o);
    FAIL("an unknown integrator was accepted");
  } catch (const InvalidInput& e) {
    CHECK_THAT(e.what(), Catch::Contains("cvodeBdf"));
  }
  o.relativeTolerance = -1;
  CHECK_THROWS_AS(makeTimeIntegrator("arkodeErk", *scene.problem, o), InvalidInput);
  CHECK_THROWS_AS(makeTimeIntegrator("cvodeBdf", *scene.problem, o), InvalidInput);
}

TEST_CASE("central difference, ARKODE ERK and CVODE BDF agree on the same semi-discrete system", "[dynamics]") {
  DynamicScene scene = makeStiffInclusions(smallPlate());
  DynamicProblem& problem = *scene.problem;
  IntegratorOptions ref;
  ref.timeStep = 0.1 * estimateStabilityLimit(problem).criticalStep;
  auto cd = makeTimeIntegrator("centralDifference", problem, ref);
  cd->advanceTo(scene.endTime);
  const std::vector<double> u(cd->displacement(), cd->displacement() + problem.dofs());
  const double work = cd->externalWork();
  REQUIRE(work > 0);

  IntegratorOptions erk;
  erk.relativeTolerance = 1e-9;
  erk.absoluteTolerance = 1e-16;
  erk.velocityTolerance = 1e-10;
  auto rk = makeTimeIntegrator("arkodeErk", problem, erk);
  rk->advanceTo(scene.endTime);
  CHECK(rk->time() == scene.endTime);
  CHECK(relativeL2(rk->displacement(), u) < 1e-4);
  CHECK(rk->externalWork() == Approx(work).epsilon(1e-4));

  IntegratorOptions bdf = erk;
  bdf.relativeTolerance = 1e-7;
  auto implicit = makeTimeIntegrator("cvodeBdf", problem, bdf);
  implicit->advanceTo(scene.endTime);
  CHECK(relativeL2(implicit->displacement(), u) < 1e-3);
  CHECK(implicit->externalWork() == Approx(work).epsilon(1e-3));
  CHECK(implicit->stats().jacobianProducts > 0);
  CHECK(implicit->stats().preconditionerSetups > 0);
}
