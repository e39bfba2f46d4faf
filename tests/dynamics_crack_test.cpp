#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "scenes/bending_test.hpp"
#include "scenes/crack_zone.hpp"
#include "scenes/dynamic_run.hpp"
#include "scenes/plexiglass_crack.hpp"

using namespace peristep;

TEST_CASE("Plexiglass crack scene: boundary conditions, energy balance and a growing crack", "[dynamics]") {
  PlexiglassCrackSpec spec;  // eps = 8 mm, h = eps/2: the coarsest level of 001 Sec. 6.1.2
  spec.meshRatio = 2;
  DynamicScene scene = makePlexiglassCrack(spec);
  std::size_t material = 0;
  for (std::size_t p = 0; p < scene.cloud.size(); ++p) material += scene.cloud.isVoid(p) ? 0 : 1;
  CHECK(material == 25 * 29);  // 0.1 m square plus an 8 mm collar above and below
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

// 001 Sec. 6.2: the two-notch beam fractures from both notches, each in a narrow band. eps = 3 mm is the
// coarsest horizon at which both notches grow here (at 6 mm one takes all the growth).
TEST_CASE("bending with two notches: a sharp crack grows from each", "[dynamics]") {
  BendingSpec spec;
  spec.cracks = 2;
  spec.horizon = 3e-3;
  spec.meshRatio = 3;
  spec.timeStep = 0.01e-6;
  spec.endTime = 160e-6;
  DynamicScene scene = makeBendingTest(spec);
  DynamicRunOptions o;
  o.reportInterval = 160e-6;
  std::vector<double> u;
  runDynamicScene(scene, o, [&](const TimeIntegrator& it, const EnergyRecord&) {
    u.assign(it.displacement(), it.displacement() + scene.problem->dofs());
  });
  std::vector<double> Z(scene.cloud.size());
  scene.model->damage(u.data(), Z.data());
  const std::vector<std::vector<CrackBandRow>> bands = crackBands(scene, Z);
  REQUIRE(bands.size() == 2);
  const double h = scene.h(), eps = spec.horizon;
  for (const std::vector<CrackBandRow>& rows : bands) {
    REQUIRE(rows.size() >= 10);                   // grown at least 10 mm
    for (std::size_t k = 1; k < rows.size(); ++k)  // one connected band, no row skipped
      CHECK(rows[k].advance - rows[k - 1].advance == Approx(h));
    std::vector<double> widths;
    for (const CrackBandRow& r : rows) widths.push_back(r.width(h));
    std::sort(widths.begin(), widths.end());
    CHECK(widths[widths.size() / 2] <= 2 * eps);  // sharp: measured 5 mm = 5 h
    CHECK(widths.back() <= 3 * eps);
  }
}

TEST_CASE("scene specifications are validated", "[dynamics]") {
  PlexiglassCrackSpec p;
  p.meshRatio = 3;  // h = 8/3 mm does not divide 0.1 m
  CHECK_THROWS_AS(makePlexiglassCrack(p), InvalidInput);
  BendingSpec b;
  b.cracks = 3;
  CHECK_THROWS_AS(makeBendingTest(b), InvalidInput);
}
