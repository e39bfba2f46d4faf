// The Plexiglass crack of 001 Sec. 6.1 (scene set-up: component/scenes/plexiglass_crack.hpp).
//
// How to run:
//   plexiglass_crack rates  <eps_mm> <T_us> [csv]           rate estimate 001:(106), h = eps/2, eps/4, eps/8
//   plexiglass_crack energy <eps_mm> <eps/h> <T_us> [csv] [--nu v]   energy bookkeeping and Griffith check
// What it shows: "rates" prints ||u1 - u2||, ||u2 - u3|| and the rate b every 2 us (001 Fig. 7);
// "energy" prints kinetic, elastic and external work, their balance, the crack-zone energy P.E. and
// G_c x crack length (001 Fig. 6), with wall time and peak memory, then the crack-zone energy per
// unit length row by row along the crack at the end time, and a least-squares line P.E. = s G_c (l - d)
// over the reports while the crack grows: s is the rate at which the crack zone gains energy per unit
// of growth (the Griffith rate when s = 1), d the length whose energy the tip's process zone lacks.
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "energy_table.hpp"
#include "core/memory.hpp"
#include "core/timer.hpp"
#include "scenes/dynamic_run.hpp"
#include "scenes/mesh_convergence.hpp"
#include "scenes/plexiglass_crack.hpp"

using namespace peristep;

namespace {

int rates(double eps, double T, const char* csvPath) {
  const double ratios[3] = {2, 4, 8};
  std::vector<std::vector<std::vector<double>>> snapshots(3);  // [mesh][report][dof]
  std::vector<DynamicScene> scenes;
  std::vector<double> seconds;
  for (int m = 0; m < 3; ++m) {
    PlexiglassCrackSpec spec;
    spec.horizon = eps;
    spec.meshRatio = ratios[m];
    scenes.push_back(makePlexiglassCrack(spec));
    DynamicRunOptions o;
    o.endTime = T;
    const Stopwatch clock;
    const DynamicRunResult r = runDynamicScene(scenes.back(), o, [&](const TimeIntegrator& integrator, const EnergyRecord&) {
      snapshots[static_cast<std::size_t>(m)].emplace_back(integrator.displacement(),
                                                          integrator.displacement() + scenes.back().problem->dofs());
    });
    seconds.push_back(clock.seconds());
    std::printf("h = eps/%g: %zu points, %zu bonds, %ld steps, %.1f s, final crack length %.4f m\n", ratios[m],
                scenes.back().cloud.materialPoints(), scenes.back().model->bonds().bonds(), r.stats.steps, seconds.back(),
                r.records.back().crackLength);
    std::fflush(stdout);
  }
  std::FILE* csv = csvPath ? std::fopen(csvPath, "w") : nullptr;
  if (csv) std::fprintf(csv, "t_us,d12,d23,rate\n");
  std::printf("%8s %14s %14s %8s\n", "t [us]", "||u1-u2||", "||u2-u3||", "rate");
  for (std::size_t k = 1; k < snapshots[0].size(); ++k) {
    const double d12 = nestedL2Difference(scenes[0], snapshots[0][k].data(), scenes[1], snapshots[1][k].data());
    const double d23 = nestedL2Difference(scenes[1], snapshots[1][k].data(), scenes[2], snapshots[2][k].data());
    const double b = rateEstimate(d12, d23, 2.0);
    const double t = 2.0 * static_cast<double>(k);
    std::printf("%8.1f %14.6e %14.6e %8.3f\n", t, d12, d23, b);
    if (csv) std::fprintf(csv, "%g,%.9e,%.9e,%.6f\n", t, d12, d23, b);
  }
  if (csv) std::fclose(csv);
  std::printf("peak memory %.0f MB\n", static_cast<double>(peakMemoryBytes()) / 1e6);
  return 0;
}

// Where the crack-zone energy sits at the end: P.E. of each lattice row (points with Z > 1) per unit
// crack length, with the pre-crack left out and counted (energy_table.hpp). Rows well behind the tip
// hold G_c per unit length when the model reproduces Griffith; the rows of the process zone at the tip
// (Z > 1 but bonds not yet fully softened) hold less.
// y is measured from D's bottom face, as in 001 Sec. 6.1.
void crackProfile(DynamicScene& scene, const std::vector<double>& u, double bottomFace) {
  const std::size_t n = scene.cloud.size();
  const double Gc = scene.model->material().fractureEnergy(), h = scene.h();
  std::vector<double> Z(n), e(n), perRow[2] = {std::vector<double>(scene.ny, 0.0), std::vector<double>(scene.ny, 0.0)};
  for (const PreCrack mode : {PreCrack::leftOut, PreCrack::counted}) {
    scene.model->damage(u.data(), Z.data(), mode);
    scene.model->tensileEnergyDensity(u.data(), e.data(), mode);
    std::vector<double>& row = perRow[mode == PreCrack::counted];
    for (std::size_t p = 0; p < n; ++p)
      if (scene.material[p] && Z[p] > 1.0) row[p / scene.nx] += scene.model->pointVolume(p) * e[p] / h;
  }
  std::printf("crack-zone energy per unit length, by row (G_c = %g J/m^2; * = pre-crack counted):\n%10s %12s %8s %8s\n",
              Gc, "y [m]", "J/m^2", "/G_c", "*/G_c");
  for (std::size_t k = 0; k < scene.ny; ++k)
    if (perRow[1][k] > 0)
      std::printf("%10.5f %12.2f %8.3f %8.3f\n", scene.y0 + static_cast<double>(k) * h - bottomFace, perRow[0][k], perRow[0][k] / Gc,
                  perRow[1][k] / Gc);
}

int energy(double eps, double ratio, double T, double nu, const char* csvPath) {
  PlexiglassCrackSpec spec;
  spec.horizon = eps;
  spec.meshRatio = ratio;
  spec.material.poissonRatio = nu;
  DynamicScene scene = makePlexiglassCrack(spec);
  const double Gc = scene.model->material().fractureEnergy();
  std::printf("eps = %g mm, h = %g mm: %zu points, %zu bonds\n", eps * 1e3, scene.h() * 1e3, scene.cloud.materialPoints(),
              scene.model->bonds().bonds());
  DynamicRunOptions o;
  o.endTime = T;
  o.reportInterval = 1e-6;
  const Stopwatch clock;
  std::vector<double> u, lengths, energies;  // while the crack grows
  DynamicRunResult r;
  {
    bench::EnergyTable table(Gc, csvPath);
    r = runDynamicScene(scene, o, [&](const TimeIntegrator& integrator, const EnergyRecord& e) {
      u.assign(integrator.displacement(), integrator.displacement() + scene.problem->dofs());
      if (e.crackLength > 0) lengths.push_back(e.crackLength), energies.push_back(e.fractureEnergy);
      table.row(e);
    });
  }
  std::printf("wall time %.1f s for %ld steps (%.3e bond-updates/s), peak memory %.0f MB\n", clock.seconds(), r.stats.steps,
              static_cast<double>(scene.model->bonds().bonds()) * static_cast<double>(r.stats.steps) / clock.seconds(),
              static_cast<double>(peakMemoryBytes()) / 1e6);
  crackProfile(scene, u, -0.5 * spec.side);
  if (lengths.size() >= 2) {
    double ml = 0, me = 0, sll = 0, sle = 0;
    const double n = static_cast<double>(lengths.size());
    for (std::size_t k = 0; k < lengths.size(); ++k) ml += lengths[k] / n, me += energies[k] / n;
    for (std::size_t k = 0; k < lengths.size(); ++k) {
      sll += (lengths[k] - ml) * (lengths[k] - ml);
      sle += (lengths[k] - ml) * (energies[k] - me);
    }
    const double slope = sle / sll, offset = ml - me / slope;
    std::printf("growth: P.E. = %.4f G_c (l - %.3f mm) over %zu reports with l > 0 (l up to %.2f mm)\n", slope / Gc,
                offset * 1e3, lengths.size(), lengths.back() * 1e3);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"plexiglass_crack: the Plexiglass crack of 001 Sec. 6.1"};
  app.require_subcommand(1);
  double eps = 0, ratio = 0, T = 0, nu = PlexiglassCrackSpec{}.material.poissonRatio;
  std::string csv;
  CLI::App* ratesCmd = app.add_subcommand("rates", "rate estimate 001:(106) from h = eps/2, eps/4, eps/8");
  ratesCmd->add_option("eps_mm", eps, "horizon eps [mm]")->required()->check(CLI::PositiveNumber);
  ratesCmd->add_option("T_us", T, "end time [us]")->required()->check(CLI::PositiveNumber);
  ratesCmd->add_option("csv", csv, "write the table as CSV to this file");
  CLI::App* energyCmd = app.add_subcommand("energy", "energy bookkeeping and Griffith check");
  energyCmd->add_option("eps_mm", eps, "horizon eps [mm]")->required()->check(CLI::PositiveNumber);
  energyCmd->add_option("eps_over_h", ratio, "eps/h")->required()->check(CLI::PositiveNumber);
  energyCmd->add_option("T_us", T, "end time [us]")->required()->check(CLI::PositiveNumber);
  energyCmd->add_option("csv", csv, "write the table as CSV to this file");
  energyCmd->add_option("--nu", nu, "Poisson ratio (0.25: tensile force only; other values add the hydrostatic force)")
      ->capture_default_str();
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  const char* csvPath = csv.empty() ? nullptr : csv.c_str();
  try {
    if (ratesCmd->parsed()) return rates(eps * 1e-3, T * 1e-6, csvPath);
    return energy(eps * 1e-3, ratio, T * 1e-6, nu, csvPath);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
