#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "scenes/bending_test.hpp"
#include "scenes/dynamic_run.hpp"
#include "scenes/plexiglass_crack.hpp"

using namespace peristep;

TEST_CASE("Plexiglass crack scene: boundary conditions, energy balance and a growing crack", "[dynamics]") {
  PlexiglassCrackSpec spec;  // eps = 8 mm, h = eps/2: the coarsest level of 001 Sec. 6.1.2
  spec.meshRatio = 2;
  DynamicScene scene = makePlexiglassCrack(spec);
  CHECK(scene.cloud.size() == 25 * 29);  // 0.1 m square plus an 8 mm collar above and below
  DynamicRunOptions o;
  o.reportInterval = 2e-6;
  const DynamicRunResult r = runDynamicScene(scene, o);
  REQUIRE(r.records.size() == 18);
  const EnergyRecord& first = r.records.front();
  CHECK(first.kinetic > 0);  // the bottom strips start at +-1 m/s
  for (const EnergyRecord& e : r.records) {
    // Kinetic + elastic energy changes only by the work of the reactions on the moving strips.
    CHECK(std::abs(e.balance(first)) <= 1e-3 * (e.externalWork + first.kinetic));
    CHECK(e.fractureEnergy <= e.elastic);
  }
  const EnergyRecord& last = r.records.back();
  CHECK(last.time == Approx(34e-6));
  CHECK(last.externalWork > 10 * first.kinetic);
  CHECK(last.maxDamage > 1.0);
  CHECK(last.crackLength > 0.0);
  CHECK(last.crackLength < 0.08 - 1e-9);
  CHECK(r.stats.steps == 8500);  // dt = 0.004 us to 34 us
}

TEST_CASE("bending scene: supports hold, the load does work, energy balances", "[dynamics]") {
  BendingSpec spec;
  spec.cracks = GENERATE(1, 2);
  spec.horizon = 6e-3;  // coarse: the test checks the set-up and the bookkeeping, not the fracture
  spec.meshRatio = 3;
  spec.timeStep = 0.02e-6;
  spec.endTime = 20e-6;
  DynamicScene scene = makeBendingTest(spec);
  CHECK(scene.cracks.size() == static_cast<std::size_t>(spec.cracks));
  DynamicRunOptions o;
  o.reportInterval = 5e-6;
  std::vector<double> uy;
  const DynamicRunResult r = runDynamicScene(scene, o, [&](const TimeIntegrator& it, const EnergyRecord&) {
    uy.assign(it.displacement(), it.displacement() + scene.problem->dofs());
  });
  const EnergyRecord& first = r.records.front();
  for (const EnergyRecord& e : r.records) CHECK(std::abs(e.balance(first)) <= 1e-3 * std::max(e.externalWork, 1e-30));
  CHECK(r.records.back().externalWork > 0);
  std::size_t held = 0;
  double sag = 0;
  for (std::size_t d = 0; d < scene.problem->dofs(); ++d) {
    if (scene.problem->prescribed()[d]) {
      ++held;
      CHECK(uy[d] == 0.0);
    }
    sag = std::min(sag, d % 2 ? uy[d] : 0.0);
  }
  CHECK(held > 0);
  CHECK(sag < 0);  // the beam moves down under the load
}

TEST_CASE("scene specifications are validated", "[dynamics]") {
  PlexiglassCrackSpec p;
  p.meshRatio = 3;  // h = 8/3 mm does not divide 0.1 m
  CHECK_THROWS_AS(makePlexiglassCrack(p), InvalidInput);
  BendingSpec b;
  b.cracks = 3;
  CHECK_THROWS_AS(makeBendingTest(b), InvalidInput);
}
