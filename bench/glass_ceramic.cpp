// The glass-ceramic specimen of 000 Sec. 5 (Table 1): load it until the crack crosses, report crack
// shares, K_IC (000:(5.2)-(5.3)), wall time and peak memory; write the load-displacement curve as CSV.
//
//   glass_ceramic [--h-um 8] [--fraction 0.2] [--seed 1] [--max-load-um 1] [--step-um 0.004]
//                 [--solver umfpack] [--driver zone|stale|reference] [--csv curve.csv] [--png damage.png]
//                 [--checkpoint state.bin] [--checkpoint-minutes 10]      (--help lists them)
//
// --checkpoint writes the run's state to that file (atomically) every 10 minutes or so, also inside a load
// step between sub-iterations; a rerun with the same options continues from it, bit for bit, so a full-size
// run can be spread over several sittings (under other options it refuses; remove the file to start
// afresh). Wall time and the profile add up over the sittings.
//
// --driver reference runs the reference driver (a new factorization at every change of the matrix, no GMRES;
// --reference is short for it), --driver stale the GMRES driver that preceded the crack zone;
// the "crack history" hash printed at the end is equal for two runs exactly when they broke the same
// bonds in the same order at every load step.
//
// The "factorization ratio" is the run's wall time over the wall time of one numeric factorization of the
// initial matrix (median of three, timed at start-up in the same process and not counted in the run's
// wall time): a measure of the driver from which the machine's speed mostly cancels.
//
// --png draws the final damage over the microstructure with the host's colours (the picture
// `peristep run` leaves), so one long run yields both the numbers and the picture.
// h = 2 um is the paper's full size (413 x 213 = 87969 points with the collar).
#include <dlfcn.h>
#include <malloc.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>

#include "bench_cli.hpp"
#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "core/memory.hpp"
#include "core/timer.hpp"
#include "damage_picture.hpp"
#include "linalg/linear_solver.hpp"
#include "process_settings.hpp"
#include "scenes/glass_ceramic.hpp"

using namespace peristep;

namespace {

constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;

// FNV-1a over 64-bit words. Bonds only break, so the broken list at the end and its length after every
// load step together are the whole crack history.
std::uint64_t fnv1a(std::uint64_t h, std::uint64_t word) {
  for (int b = 0; b < 8; ++b) h = (h ^ ((word >> (8 * b)) & 0xff)) * 1099511628211ull;
  return h;
}

// Wall seconds of one numeric factorization of the specimen's initial matrix with a solver of its own:
// the median of three, as the machine is shared.
double oneFactorizationSeconds(const GlassCeramicSpecimen& g, const std::string& solverName) {
  const std::unique_ptr<LinearSolver> solver = makeLinearSolver(linearSolverKind(solverName));
  const CsrMatrix& A = g.solver().matrix();
  solver->analyze(A);
  std::array<double, 3> seconds;
  for (double& s : seconds) {
    Stopwatch clock;
    solver->factorize(A);
    s = clock.seconds();
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[1];
}

// The options that define the run: a checkpoint is only continued under the same ones.
struct RunOptions {
  double hUm, fraction, stepUm;
  std::uint64_t seed;
  FactorizationReuse driver;
  FactorPrecision factors;
  bool operator==(const RunOptions&) const = default;
};

// What a sitting must carry to the next one besides the solver state: the options, where the loading
// stands and the totals so far.
struct Progress {
  RunOptions options;
  int step = 1;  // load step in progress (1-based)
  double seconds = 0;
  LoadStepReport sum;
  LoadStepReport stepSoFar;  // of the load step in progress, up to the checkpoint
  std::uint64_t history = kFnvOffset;  // hash of the broken-bond counts after every finished load step
};

void writeCheckpoint(const std::string& path, const Progress& p, const GlassCeramicSpecimen& g) {
  ByteWriter w;
  w.put(p);
  w.putArray(g.saveState());
  const std::vector<std::uint8_t> bytes = w.take();
  const std::string partial = path + ".partial";
  std::ofstream out(partial, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw InvalidInput("cannot write the checkpoint " + partial);
  std::filesystem::rename(partial, path);  // atomic: the file holds the old state or the whole new one
}

Progress readCheckpoint(const std::string& path, const RunOptions& options, GlassCeramicSpecimen& g) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ByteReader r(bytes);
  const auto p = r.get<Progress>();
  if (!(p.options == options))
    throw InvalidInput("checkpoint " + path + " belongs to another run (h, fraction, step, seed or driver differ); "
                       "remove it to start afresh");
  const auto state = r.getArray<std::uint8_t>();
  r.expectEnd();
  g.restoreState(state);
  return p;
}

}  // namespace

int main(int argc, char** argv) try {
  peristep::startWithProcessSettings(argv);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines appear as they come, also in a log file
  double hUm = 8, fraction = 0.2, maxLoadUm = 1.0, stepUm = 0.004, checkpointMinutes = 10;
  std::uint64_t seed = 1;
  bool reference = false;
  std::string driver = "zone", solver = "umfpack", csvPath, pngPath, checkpointPath;
  CLI::App app{"glass_ceramic: the glass-ceramic fracture specimen of 000 Sec. 5, with a profile of the driver"};
  app.add_option("--h-um", hUm, "grid spacing h in um (2 = the paper's full size)")->capture_default_str();
  app.add_option("--fraction", fraction, "target crystal fraction")->capture_default_str();
  app.add_option("--seed", seed, "microstructure seed")->capture_default_str();
  app.add_option("--max-load-um", maxLoadUm, "largest opening U_D in um")->capture_default_str();
  app.add_option("--step-um", stepUm, "load increment in um")->capture_default_str();
  app.add_option("--solver", solver, "sparse solver")->capture_default_str()->check(CLI::IsMember(linearSolverNames()));
  const std::map<std::string, FactorizationReuse> drivers{{"zone", FactorizationReuse::CrackZone},
                                                          {"stale", FactorizationReuse::StaleAsPreconditioner},
                                                          {"reference", FactorizationReuse::RefactorizeEveryChange}};
  app.add_option("--driver", driver,
                 "zone: crack-zone Schur complement (production); stale: GMRES with an older factorization; "
                 "reference: refactorize at every change of the matrix")
      ->capture_default_str()
      ->check(CLI::IsMember(drivers));
  app.add_flag("--reference", reference, "short for --driver reference");
  const std::map<std::string, FactorPrecision> precisions{{"double", FactorPrecision::Double},
                                                          {"single", FactorPrecision::Single}};
  std::string factors = kZoneFactorPrecision == FactorPrecision::Single ? "single" : "double";
  app.add_option("--factors", factors, "precision of the crack zone's sparse factors (refined in double)")
      ->capture_default_str()
      ->check(CLI::IsMember(precisions));
  app.add_option("--csv", csvPath, "load-displacement curve and per-step profile (CSV)");
  app.add_option("--png", pngPath, "final damage picture (PNG)");
  app.add_option("--checkpoint", checkpointPath, "checkpoint file: saved while running, continued from if present");
  app.add_option("--checkpoint-minutes", checkpointMinutes, "minutes between checkpoints")->capture_default_str();
  if (const auto stop = peristep::bench::parseArguments(app, argc, argv)) return *stop;
  GlassCeramicSpec spec;
  spec.grid.nx = static_cast<std::size_t>(std::lround(800.0 / hUm)) + 1;
  spec.grid.ny = static_cast<std::size_t>(std::lround(400.0 / hUm)) + 1;
  spec.crystalFraction = fraction;
  spec.seed = seed;
  spec.linearSolver = linearSolverKind(solver);
  if (reference) driver = "reference";
  spec.reuse = drivers.at(driver);
  spec.zonePrecision = precisions.at(factors);
  if (spec.reuse != FactorizationReuse::CrackZone) {
    // Keep freed memory in the process: every UMFPACK factorization and assembly allocates (and frees)
    // hundreds of MB to GB of the same sizes, and from fresh mmap'd pages each costs page faults. h = 4
    // um, f = 0.2, to U_D = 0.232 um: 169 -> 147 s wall, system time 22 -> 0.8 s; peak memory 960 -> 1570
    // MB. Not for the crack-zone driver: MUMPS' work arrays differ in size from one zone to the next, and
    // the heap they would leave behind grew to 14.9 GB at h = 2 um.
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
  }

  Stopwatch total;
  GlassCeramicSpecimen g(spec);
  std::printf("# glass-ceramic h = %g um, %zu points, f = %.3f (target %.2f), seed %llu, set-up %.2f s\n", hUm,
              g.solver().discretization().cloud.size(), g.measuredCrystalFraction(), fraction,
              static_cast<unsigned long long>(seed), total.seconds());
  Stopwatch timing;
  const double factorizationSeconds = oneFactorizationSeconds(g, solver);
  const double timingSeconds = timing.seconds();  // not part of the specimen's wall time
  // The timing's solver (UMFPACK: ~4 GB at h = 2 um) may set the process' peak: the run's own is counted apart.
  const std::size_t setupPeak = peakMemoryBytes();
  const bool runPeakKnown = resetPeakMemory();
  // The kernels set the speed of every dense product (process_settings.hpp): say which ran.
  using CoreName = const char* (*)();
  const auto coreName = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  std::printf("# driver: %s, %s factors; one factorization of the initial matrix (%s) %.2f s (median of 3); "
              "OpenBLAS kernels %s\n",
              driver.c_str(), factors.c_str(), solver.c_str(), factorizationSeconds, coreName ? coreName() : "(not OpenBLAS)");
  Progress run;
  run.options = {hUm, fraction, stepUm, seed, spec.reuse, spec.zonePrecision};
  const bool resumed = !checkpointPath.empty() && std::filesystem::exists(checkpointPath);
  if (resumed) {
    run = readCheckpoint(checkpointPath, run.options, g);
    std::printf("# resumed from %s in load step %d (%.0f s before)\n", checkpointPath.c_str(), run.step, run.seconds);
  }
  const auto elapsed = [&] { return run.seconds + total.seconds() - timingSeconds; };
  if (!checkpointPath.empty()) {
    g.onSubIteration([&, sinceSaved = Stopwatch()](const LoadStepReport& soFar) mutable {
      if (sinceSaved.seconds() < 60 * checkpointMinutes) return;
      sinceSaved.lap();
      Progress now = run;
      now.seconds = elapsed();
      now.stepSoFar += soFar;  // a step resumed twice carries both earlier parts
      writeCheckpoint(checkpointPath, now, g);
    });
  }
  std::ofstream csv;
  if (!csvPath.empty()) {
    csv.open(csvPath, resumed ? std::ios::app : std::ios::trunc);
    if (!resumed)
      csv << "load_um,reaction_force_N_per_m,broken_pairs,sub_iterations,factorizations,krylov_iterations,"
             "assembly_s,factorization_s,solve_s,bond_check_s,seconds\n";
  }
  std::printf("%9s %14s %8s %5s %5s %6s %8s\n", "U_D um", "force N/m", "broken", "sub", "fact", "krylov", "time s");
  const int steps = static_cast<int>(std::lround(maxLoadUm / stepUm));
  LoadStepReport& sum = run.sum;  // totals over the run, for the profile line
  for (; run.step <= steps && !g.crackReachedRightEdge(); ++run.step) {
    const double U = run.step * stepUm * 1e-6;
    LoadStepReport r = run.stepSoFar;  // the earlier sittings' part of a resumed step
    r += g.advance(U);
    run.stepSoFar = {};
    sum += r;
    const std::size_t broken = g.solver().brokenByLoading().size();
    run.history = fnv1a(run.history, broken);
    if (csv)
      csv << U * 1e6 << ',' << g.reactionForce() << ',' << broken << ',' << r.subIterations << ','
          << r.factorizations << ',' << r.krylovIterations << ',' << r.assemblySeconds << ','
          << r.factorizationSeconds << ',' << r.solveSeconds << ',' << r.bondCheckSeconds << ',' << elapsed()
          << std::endl;
    if (r.newlyBroken > 0 || run.step % 25 == 0)
      std::printf("%9.3f %14.6e %8zu %5d %5d %6d %8.1f\n", U * 1e6, g.reactionForce(), broken, r.subIterations,
                  r.factorizations, r.krylovIterations, elapsed());
  }
  std::printf("profile: %d load steps, %d solves, %d factorizations %.1f s, %d GMRES iterations, %d dense zone LUs, "
              "%lld substitutions, solves %.1f s, assembly %.1f s, bond checks %.1f s; "
              "last zone factors %lld entries; GMRES rescues %d; fallbacks to double factors %d\n",
              run.step - 1, sum.subIterations, sum.factorizations, sum.factorizationSeconds, sum.krylovIterations,
              sum.denseFactorizations, static_cast<long long>(sum.substitutions), sum.solveSeconds,
              sum.assemblySeconds, sum.bondCheckSeconds, static_cast<long long>(g.solver().zoneFactorEntries()),
              sum.krylovRescues, sum.precisionFallbacks);
  std::printf("factorization ratio: wall %.1f s / one factorization %.2f s = %.1f\n", elapsed(), factorizationSeconds,
              elapsed() / factorizationSeconds);
  std::uint64_t history = run.history;
  for (std::size_t k : g.solver().brokenByLoading()) history = fnv1a(history, k);
  std::printf("crack history: %zu broken pairs, hash %016llx\n", g.solver().brokenByLoading().size(),
              static_cast<unsigned long long>(history));
  const CrackShares L = g.crackShares();
  std::printf("crack reached the right edge: %s\n", g.crackReachedRightEdge() ? "yes" : "no");
  std::printf("crack length: glass %.1f um (%.0f%%), crystal %.1f um (%.0f%%), interface %.1f um (%.0f%%); W = %.1f um\n",
              L.glass * 1e6, 100 * L.glass / L.total(), L.crystal * 1e6, 100 * L.crystal / L.total(),
              L.interface * 1e6, 100 * L.interface / L.total(), g.projectedCrackLength() * 1e6);
  const double runPeakMB = static_cast<double>(peakMemoryBytes()) / 1048576.0;
  std::printf("G_IC = %.3f J/m^2, K_IC = %.3f MPa m^0.5, wall %.1f s, peak %.0f MB", g.energyReleaseRate(),
              g.toughnessKIC() / 1e6, elapsed(), std::max(static_cast<double>(setupPeak) / 1048576.0, runPeakMB));
  if (runPeakKnown) std::printf(" (the run after the timing: %.0f MB)", runPeakMB);
  std::printf("\n");
  if (!pngPath.empty()) {
    host::writePng(pngPath, host::damagePicture(spec.grid.ny, spec.grid.nx, g.damage(), g.youngsModulus()));
    std::printf("damage picture: %s\n", pngPath.c_str());
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "glass_ceramic: " << e.what() << '\n';
  return 1;
}
