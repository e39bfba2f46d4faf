#include <catch2/catch.hpp>

#include "scenes/dynamic_run.hpp"
#include "scenes/mesh_convergence.hpp"
#include "scenes/plexiglass_crack.hpp"

using namespace peristep;

// 001 Sec. 6.1.2, Fig. 7 for eps = 8 mm: the rate estimate 001:(106) from h = eps/2, eps/4, eps/8.
// The test covers 0-6 us (about 30 s of CPU); the full 34 us run is bench/plexiglass_crack
// ("rates 8 34"), see docs/verification.md.
TEST_CASE("Plexiglass crack, eps = 8 mm: the rate estimate 001:(106) stays >= 1 (first 6 us)", "[dynamics][slow]") {
  const double endTime = 6e-6;
  std::vector<DynamicScene> scenes;
  std::vector<std::vector<std::vector<double>>> snapshots(3);
  for (const double ratio : {2.0, 4.0, 8.0}) {
    PlexiglassCrackSpec spec;
    spec.horizon = 8e-3;
    spec.meshRatio = ratio;
    scenes.push_back(makePlexiglassCrack(spec));
    DynamicRunOptions o;
    o.endTime = endTime;
    auto& mine = snapshots[scenes.size() - 1];
    const DynamicScene& scene = scenes.back();
    runDynamicScene(scenes.back(), o, [&](const TimeIntegrator& it, const EnergyRecord&) {
      mine.emplace_back(it.displacement(), it.displacement() + scene.problem->dofs());
    });
  }
  REQUIRE(snapshots[0].size() == 4);  // t = 0, 2, 4, 6 us
  for (std::size_t k = 1; k < snapshots[0].size(); ++k) {
    const double d12 = nestedL2Difference(scenes[0], snapshots[0][k].data(), scenes[1], snapshots[1][k].data());
    const double d23 = nestedL2Difference(scenes[1], snapshots[1][k].data(), scenes[2], snapshots[2][k].data());
    INFO("t = " << 2 * k << " us: ||u1 - u2|| = " << d12 << ", ||u2 - u3|| = " << d23);
    CHECK(d23 < d12);
    CHECK(rateEstimate(d12, d23, 2.0) >= 1.0);
  }
}
