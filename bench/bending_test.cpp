// The pre-cracked beam under bending of 001 Sec. 6.2 (set-up: component/scenes/bending_test.hpp).
//
// How to run:  bending_test <cracks 1|2> <eps_mm> <eps/h> <dt_us> <T_us> [csv]
//   001 itself: bending_test 1 0.75 3 0.0035 350 (200k points, 1e5 steps: about an hour here).
// What it shows: every 10 us the kinetic and elastic energy, the work of the load, their balance,
// the crack-zone energy P.E. against G_c x crack growth (001 Fig. 10; also with the pre-crack counted,
// see energy_table.hpp), then wall time.
#include <cstdio>
#include <cstdlib>

#include "energy_table.hpp"
#include "core/memory.hpp"
#include "core/timer.hpp"
#include "scenes/bending_test.hpp"
#include "scenes/dynamic_run.hpp"

using namespace peristep;

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s <cracks 1|2> <eps_mm> <eps/h> <dt_us> <T_us> [csv]\n", argv[0]);
    return 2;
  }
  try {
    BendingSpec spec;
    spec.cracks = std::atoi(argv[1]);
    spec.horizon = std::atof(argv[2]) * 1e-3;
    spec.meshRatio = std::atof(argv[3]);
    spec.timeStep = std::atof(argv[4]) * 1e-6;
    spec.endTime = std::atof(argv[5]) * 1e-6;
    DynamicScene scene = makeBendingTest(spec);
    std::printf("bending, %d pre-crack(s): eps = %g mm, h = %g mm, %zu points, %zu bonds, dt = %g us\n", spec.cracks,
                spec.horizon * 1e3, scene.h() * 1e3, scene.cloud.size(), scene.model->bonds().bonds(), spec.timeStep * 1e6);
    DynamicRunOptions o;
    o.reportInterval = 10e-6;
    const Stopwatch clock;
    DynamicRunResult r;
    {
      bench::EnergyTable table(scene.model->material().fractureEnergy(), argc > 6 ? argv[6] : nullptr);
      r = runDynamicScene(scene, o, [&](const TimeIntegrator&, const EnergyRecord& e) { table.row(e); });
    }
    std::printf("wall time %.1f s for %ld steps, peak memory %.0f MB\n", clock.seconds(), r.stats.steps,
                static_cast<double>(peakMemoryBytes()) / 1e6);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
