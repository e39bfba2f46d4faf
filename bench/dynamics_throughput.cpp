// Bond-update throughput of the state-based force (001:(14)-(15)) inside central-difference steps,
// against the memory bandwidth measured in the same run.
//
// How to run:  dynamics_throughput [csv] [--side n] [--repeats r]   (OMP_NUM_THREADS=1 and 2)
// What it shows: points x bonds/point x steps / seconds for eps/h = 4 and 8 with and without the
// hydrostatic force (median of the repeats), the bytes of bond data streamed per bond update, the
// triad bandwidth (STREAM's a = b + s c, 24 B per element, best of 10 passes) measured just before
// each row, and the fraction of the streaming bound triad / (bytes per bond) the loop reaches.
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "core/timer.hpp"
#include "models/state_based_model.hpp"
#include "solvers/central_difference.hpp"

using namespace peristep;

namespace {

// CPU seconds of this process (all threads): on a shared machine wall time alone hides contention.
double cpuSeconds() {
  rusage r{};
  getrusage(RUSAGE_SELF, &r);
  return static_cast<double>(r.ru_utime.tv_sec + r.ru_stime.tv_sec) + 1e-6 * static_cast<double>(r.ru_utime.tv_usec + r.ru_stime.tv_usec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Triad a = b + s c over 3 x 128 MB (far beyond the caches) on the threads of the run: bytes per second,
// counted as STREAM counts them (24 B per element; the write-allocate read of a is not counted).
double triadBandwidth() {
  constexpr std::size_t n = std::size_t{1} << 24;
  const std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
  const auto m = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < m; ++i) a[i] = 0.0, b[i] = 1.0, c[i] = 2.0;  // first touch by the same threads
  double best = 0;
  for (int pass = 0; pass < 10; ++pass) {
    const Stopwatch clock;
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < m; ++i) a[i] = b[i] + 3.0 * c[i];
    best = std::max(best, 24.0 * static_cast<double>(n) / clock.seconds());
  }
  if (a[n / 2] != 7.0) std::fprintf(stderr, "triad: wrong result\n");
  return best;
}

struct Row {
  double epsOverH, nu;
  std::size_t points, bonds;
  int steps;
  double seconds, cpu, updatesPerSecond, bytesPerBond, gbPerSecond, triadGbPerSecond, fractionOfBound;
};

Row run(double epsOverH, double nu, std::size_t side, int steps, int repeats) {
  const double h = 0.1 / static_cast<double>(side), eps = epsOverH * h;
  GridSpec g;
  g.nx = g.ny = side;
  g.Lx = g.Ly = static_cast<double>(side - 1) * h;
  g.deltaOverH = epsOverH;
  g.collar = false;
  const PointCloud cloud = makeRectangle(g);
  StateBasedInput in;
  in.poissonRatio = nu;
  StateBasedBondOptions o;
  o.horizon = eps;
  StateBasedModel model(makeStateBasedMaterial(in, eps), buildStateBasedBonds(cloud, o));
  DynamicProblem problem(model, 1200.0);
  // A smooth small initial displacement so that every bond does real work.
  std::vector<double> u0(problem.dofs()), v0(problem.dofs(), 0.0);
  for (std::size_t p = 0; p < cloud.size(); ++p) {
    u0[2 * p] = 1e-7 * cloud.x[p] / 0.05;
    u0[2 * p + 1] = -2e-7 * cloud.y[p] * cloud.x[p] / 0.0025;
  }
  problem.setInitialState(u0, v0);
  IntegratorOptions opt;
  opt.timeStep = 1e-9;
  CentralDifference cd(problem, opt);
  double t = 2e-9;
  cd.advanceTo(t);  // warm up
  Row r{epsOverH, nu, cloud.size(), model.bonds().bonds(), steps, 0, 0, 0, 0, 0, 0, 0};
  r.triadGbPerSecond = triadBandwidth() / 1e9;
  std::vector<double> wall, cpu;
  for (int k = 0; k < repeats; ++k) {
    const double cpu0 = cpuSeconds();
    const Stopwatch clock;
    t += steps * 1e-9;
    cd.advanceTo(t);
    wall.push_back(clock.seconds());
    cpu.push_back(cpuSeconds() - cpu0);
  }
  r.seconds = median(wall);
  r.cpu = median(cpu);
  r.updatesPerSecond = static_cast<double>(r.bonds) * steps / r.seconds;
  // Streamed per stored bond and evaluation: neighbour and direction indices (4 B each) and w (8 B); with
  // the hydrostatic force a theta pass reads indices and ws (16 B) and the force pass ws as well (24 B).
  // Per pair: times stored / pairs (each point's list is padded to a group of kBondLanes).
  const StateBasedBonds& b = model.bonds();
  const double stored = static_cast<double>(b.neighbour.size()) / static_cast<double>(b.bonds());
  r.bytesPerBond = (model.material().g.active() ? 16 + 24 : 16) * stored;
  r.gbPerSecond = r.updatesPerSecond * r.bytesPerBond / 1e9;
  r.fractionOfBound = r.gbPerSecond / r.triadGbPerSecond;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dynamics_throughput: bond-updates per second of the state-based force in central-difference steps"};
  std::string csvFile;
  std::size_t side = 320;
  int repeats = 3;
  app.add_option("csv", csvFile, "write the table as CSV to this file");
  app.add_option("--side", side, "points per side of the square plate (side^2 points)")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{20}, std::size_t{2000}));
  app.add_option("--repeats", repeats, "timed runs per row; the table shows their median")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;

  const int threads = omp_get_max_threads();
  std::vector<Row> rows;
  rows.push_back(run(4.0, 0.25, side, 40, repeats));
  rows.push_back(run(8.0, 0.25, side, 12, repeats));
  rows.push_back(run(4.0, 0.22, side, 40, repeats));
  rows.push_back(run(8.0, 0.22, side, 12, repeats));
  std::printf("threads %d, median of %d runs per row\n%6s %5s %7s %9s %5s %8s %8s %12s %10s %6s %8s %8s\n", threads,
              repeats, "eps/h", "nu", "points", "bonds", "steps", "wall s", "cpu s", "bond-upd/s", "bytes/bond", "GB/s",
              "triad", "bound");
  for (const Row& r : rows)
    std::printf("%6.0f %5.2f %7zu %9zu %5d %8.3f %8.3f %12.3e %10.1f %6.2f %8.2f %7.0f%%\n", r.epsOverH, r.nu, r.points,
                r.bonds, r.steps, r.seconds, r.cpu, r.updatesPerSecond, r.bytesPerBond, r.gbPerSecond,
                r.triadGbPerSecond, 100 * r.fractionOfBound);
  std::printf("(bond-upd/s = points x bonds/point x steps / wall seconds; cpu s above wall s x threads means\n"
              " the machine was shared while it ran; triad in GB/s; bound = GB/s of bond data / triad)\n");
  if (!csvFile.empty()) {
    std::ofstream csv(csvFile);
    csv << "threads,eps_over_h,nu,points,bonds,steps,wall_s,cpu_s,bond_updates_per_s,bytes_per_bond,GB_per_s,"
           "triad_GB_per_s,fraction_of_bound\n";
    for (const Row& r : rows)
      csv << threads << ',' << r.epsOverH << ',' << r.nu << ',' << r.points << ',' << r.bonds << ',' << r.steps << ','
          << r.seconds << ',' << r.cpu << ',' << r.updatesPerSecond << ',' << r.bytesPerBond << ',' << r.gbPerSecond
          << ',' << r.triadGbPerSecond << ',' << r.fractionOfBound << '\n';
  }
  return 0;
}
