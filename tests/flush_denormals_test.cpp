#include <catch2/catch.hpp>

#include "core/flush_denormals.hpp"
#include "dynamics_test_support.hpp"
#include "solvers/stability_limit.hpp"
#include "solvers/time_integrator.hpp"

using namespace peristep;
using namespace peristep::testing;

#if defined(__SSE2__)

TEST_CASE("denormals are flushed inside the guard, and the caller's mode comes back", "[dynamics]") {
  volatile double tiny = 1e-310;  // denormal: below 2.2e-308
  const unsigned before = _mm_getcsr();
  {
    const FlushDenormals flush;
    CHECK(tiny * 1.0 == 0.0);  // DAZ: read as zero
  }
  CHECK(_mm_getcsr() == before);
  CHECK(tiny * 1.0 > 0.0);
}

TEST_CASE("the integrators leave the caller's floating-point mode as they found it", "[dynamics]") {
  const double h = 1e-3, eps = 3e-3;
  const PointCloud c = lattice(10, 10, h);
  StateBasedModel m = model(c, plexiglass(0.22, eps), eps);
  DynamicProblem problem(m, m.material().density);
  problem.setInitialState(randomField(2 * c.size(), 1e-6, 3), std::vector<double>(2 * c.size(), 0.0));
  const unsigned before = _mm_getcsr();
  for (const std::string name : {"centralDifference", "arkodeErk", "cvodeBdf"}) {
    IntegratorOptions io;
    io.timeStep = 0.5 * estimateStabilityLimit(problem).criticalStep;
    auto integrator = makeTimeIntegrator(name, problem, io);
    integrator->advanceTo(20 * io.timeStep);
    INFO(name);
    CHECK(_mm_getcsr() == before);
  }
}

#endif
