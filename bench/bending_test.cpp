// The pre-cracked beam under bending of 001 Sec. 6.2 (set-up: component/scenes/bending_test.hpp).
//
// How to run:  bending_test <cracks 1|2> <eps_mm> <eps/h> <dt_us> <T_us> [csv] [--load-depth-mm d] [--nu v]
//   --load-depth-mm: depth of the loaded band under the top edge (default 0.75 = one horizon of 001;
//   the resultant load is proportional to it, see scenes/bending_test.hpp).
//   001 itself: bending_test 1 0.75 3 0.0035 350 (200k points, 1e5 steps: about 30 min on two threads).
// What it shows: every 10 us the kinetic and elastic energy, the work of the load, their balance,
// the crack-zone energy P.E. against G_c x crack growth (001 Fig. 10; also with the pre-crack counted,
// see energy_table.hpp), then wall time, then the shape of each crack at the end time: how far its
// Z > 1 zone has grown beyond the notch and how wide that band is, row by row (a sharp crack is a
// band a few h wide).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "energy_table.hpp"
#include "core/memory.hpp"
#include "core/timer.hpp"
#include "scenes/bending_test.hpp"
#include "scenes/crack_zone.hpp"
#include "scenes/dynamic_run.hpp"

using namespace peristep;

namespace {

// Every 2 mm of advance the band's extent in x (the notches point up, so an offset to the crack's left
// is -x), then the median and widest band; x is measured from the beam's left end, as in 001 Sec. 6.2.
void printCrackBands(DynamicScene& scene, const std::vector<double>& u, double t, double leftEnd) {
  std::vector<double> Z(scene.cloud.size());
  scene.model->damage(u.data(), Z.data());
  const double h = scene.h();
  const auto every = std::max(1L, std::lround(2e-3 / h));
  const std::vector<std::vector<CrackBandRow>> bands = crackBands(scene, Z);
  std::printf("crack bands at t = %g us: the Z > 1 zone beyond each notch tip, row by row (h = %g mm, eps = %g mm)\n",
              t * 1e6, h * 1e3, scene.horizon() * 1e3);
  for (std::size_t k = 0; k < bands.size(); ++k) {
    const std::vector<CrackBandRow>& rows = bands[k];
    const double x = scene.cracks[k].x1 - leftEnd;
    std::printf("notch at x = %.1f mm: %zu rows, grown %.2f mm\n%12s %10s %10s %10s\n", x * 1e3, rows.size(),
                rows.empty() ? 0.0 : rows.back().advance * 1e3, "advance mm", "x from mm", "x to mm", "width mm");
    std::vector<double> widths;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const CrackBandRow& r = rows[i];
      widths.push_back(r.width(h));
      if ((i + 1) % static_cast<std::size_t>(every) == 0)
        std::printf("%12.2f %10.2f %10.2f %10.2f\n", r.advance * 1e3, (x - r.right) * 1e3, (x - r.left) * 1e3,
                    r.width(h) * 1e3);
    }
    if (widths.empty()) continue;
    std::sort(widths.begin(), widths.end());
    std::printf("band width: median %.2f mm, widest %.2f mm\n", widths[widths.size() / 2] * 1e3, widths.back() * 1e3);
  }
}

}  // namespace

int main(int argc, char** argv) {
  BendingSpec spec;
  double eps = 0, dt = 0, T = 0, loadDepth = spec.layout.loadDepth * 1e3;
  std::string csv;
  CLI::App app{"bending_test: the pre-cracked beam under bending of 001 Sec. 6.2"};
  app.add_option("cracks", spec.cracks, "number of pre-cracks")->required()->check(CLI::IsMember({1, 2}));
  app.add_option("eps_mm", eps, "horizon eps [mm]")->required()->check(CLI::PositiveNumber);
  app.add_option("eps_over_h", spec.meshRatio, "eps/h")->required()->check(CLI::PositiveNumber);
  app.add_option("dt_us", dt, "time step [us]")->required()->check(CLI::PositiveNumber);
  app.add_option("T_us", T, "end time [us]")->required()->check(CLI::PositiveNumber);
  app.add_option("csv", csv, "write the energy table as CSV to this file");
  app.add_option("--nu", spec.material.poissonRatio, "Poisson ratio (0.25: tensile force only; other values add the hydrostatic force)")
      ->capture_default_str();
  app.add_option("--load-depth-mm", loadDepth, "depth of the loaded band under the top edge [mm]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  try {
    spec.horizon = eps * 1e-3;
    spec.timeStep = dt * 1e-6;
    spec.endTime = T * 1e-6;
    spec.layout.loadDepth = loadDepth * 1e-3;
    DynamicScene scene = makeBendingTest(spec);
    std::printf("bending, %d pre-crack(s): eps = %g mm, h = %g mm, %zu points, %zu bonds, dt = %g us, load band %g mm deep\n",
                spec.cracks, spec.horizon * 1e3, scene.h() * 1e3, scene.cloud.materialPoints(), scene.model->bonds().bonds(),
                spec.timeStep * 1e6, spec.layout.loadDepth * 1e3);
    DynamicRunOptions o;
    o.reportInterval = 10e-6;
    const Stopwatch clock;
    DynamicRunResult r;
    std::vector<double> u;  // at the last report
    {
      bench::EnergyTable table(scene.model->material().fractureEnergy(), csv.empty() ? nullptr : csv.c_str());
      r = runDynamicScene(scene, o, [&](const TimeIntegrator& integrator, const EnergyRecord& e) {
        u.assign(integrator.displacement(), integrator.displacement() + scene.problem->dofs());
        table.row(e);
      });
    }
    std::printf("wall time %.1f s for %ld steps (%.3e bond-updates/s), peak memory %.0f MB\n", clock.seconds(),
                r.stats.steps,
                static_cast<double>(scene.model->bonds().bonds()) * static_cast<double>(r.stats.steps) / clock.seconds(),
                static_cast<double>(peakMemoryBytes()) / 1e6);
    printCrackBands(scene, u, r.records.back().time, -0.5 * spec.length);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
