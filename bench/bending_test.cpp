// The pre-cracked beam under bending of 001 Sec. 6.2 (set-up: component/scenes/bending_test.hpp).
//
// How to run:  bending_test <cracks 1|2> <eps_mm> <eps/h> <dt_us> <T_us> [csv]
//   001 itself: bending_test 1 0.75 3 0.0035 350 (200k points, 1e5 steps: about an hour here).
// What it shows: every 10 us the kinetic and elastic energy, the work of the load, their balance,
// the crack-zone energy P.E., the total crack growth l and G_c l (001 Fig. 10), then wall time.
#include <cstdio>
#include <cstdlib>

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
    const double Gc = scene.model->material().fractureEnergy();
    std::printf("bending, %d pre-crack(s): eps = %g mm, h = %g mm, %zu points, %zu bonds, dt = %g us\n", spec.cracks,
                spec.horizon * 1e3, scene.h() * 1e3, scene.cloud.size(), scene.model->bonds().bonds(), spec.timeStep * 1e6);
    std::FILE* csv = argc > 6 ? std::fopen(argv[6], "w") : nullptr;
    if (csv) std::fprintf(csv, "t_us,kinetic,elastic,work,balance,fracture_energy,crack_length,griffith,max_Z\n");
    std::printf("%7s %11s %11s %11s %11s %11s %9s %11s %7s %8s\n", "t[us]", "kinetic", "elastic", "work", "balance", "P.E.",
                "l [m]", "Gc l", "PE/GE", "max Z");
    DynamicRunOptions o;
    o.reportInterval = 10e-6;
    EnergyRecord first;
    const Stopwatch clock;
    const DynamicRunResult r = runDynamicScene(scene, o, [&](const TimeIntegrator&, const EnergyRecord& e) {
      if (e.time == 0) first = e;
      const double ge = Gc * e.crackLength;
      std::printf("%7.1f %11.4e %11.4e %11.4e %11.3e %11.4e %9.5f %11.4e %7.3f %8.1f\n", e.time * 1e6, e.kinetic, e.elastic,
                  e.externalWork, e.balance(first), e.fractureEnergy, e.crackLength, ge, ge > 0 ? e.fractureEnergy / ge : 0.0,
                  e.maxDamage);
      std::fflush(stdout);
      if (csv)
        std::fprintf(csv, "%g,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.6f\n", e.time * 1e6, e.kinetic, e.elastic, e.externalWork,
                     e.balance(first), e.fractureEnergy, e.crackLength, ge, e.maxDamage);
    });
    if (csv) std::fclose(csv);
    std::printf("wall time %.1f s for %ld steps, peak memory %.0f MB\n", clock.seconds(), r.stats.steps,
                static_cast<double>(peakMemoryBytes()) / 1e6);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
