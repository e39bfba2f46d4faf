// Bond-update throughput of the state-based force (001:(14)-(15)) inside central-difference steps.
//
// How to run:  OMP_NUM_THREADS=1 ./dynamics_throughput [csv]   and again with OMP_NUM_THREADS=2
// What it shows: points x bonds/point x steps / seconds for eps/h = 4 and 8, the bytes of bond data
// streamed per bond update and the memory bandwidth that implies (compare with ~25 GB/s on one
// thread, ~30 GB/s on two: DESIGN 8).
#include <omp.h>
#include <sys/resource.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

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

struct Row {
  double epsOverH, nu;
  std::size_t points, bonds;
  int steps;
  double seconds, cpu, updatesPerSecond, bytesPerBond, gbPerSecond;
};

Row run(double epsOverH, double nu, std::size_t side, int steps) {
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
  cd.advanceTo(2e-9);  // warm up
  const double cpu0 = cpuSeconds();
  const Stopwatch clock;
  cd.advanceTo(2e-9 + steps * 1e-9);
  const double s = clock.seconds();
  Row r{epsOverH, nu, cloud.size(), model.bonds().bonds(), steps, s, cpuSeconds() - cpu0, 0, 0, 0};
  r.updatesPerSecond = static_cast<double>(r.bonds) * steps / s;
  // Streamed per bond and evaluation: neighbour index (4 B), q (16 B), w (8 B). With the hydrostatic
  // force a theta pass reads index, q and ws (28 B) and the force pass reads ws as well (36 B).
  r.bytesPerBond = model.material().g.active() ? 28 + 36 : 28;
  r.gbPerSecond = r.updatesPerSecond * r.bytesPerBond / 1e9;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = omp_get_max_threads();
  std::vector<Row> rows;
  rows.push_back(run(4.0, 0.25, 300, 40));
  rows.push_back(run(8.0, 0.25, 200, 20));
  rows.push_back(run(4.0, 0.22, 300, 40));
  rows.push_back(run(8.0, 0.22, 200, 20));
  std::printf("threads %d\n%6s %5s %7s %9s %5s %8s %8s %12s %10s %6s\n", threads, "eps/h", "nu", "points", "bonds",
              "steps", "wall s", "cpu s", "bond-upd/s", "bytes/bond", "GB/s");
  for (const Row& r : rows)
    std::printf("%6.0f %5.2f %7zu %9zu %5d %8.3f %8.3f %12.3e %10.0f %6.2f\n", r.epsOverH, r.nu, r.points, r.bonds,
                r.steps, r.seconds, r.cpu, r.updatesPerSecond, r.bytesPerBond, r.gbPerSecond);
  std::printf("(bond-upd/s = points x bonds/point x steps / wall seconds; cpu s above wall s x threads means\n"
              " the machine was shared while it ran)\n");
  if (argc > 1) {
    std::ofstream csv(argv[1]);
    csv << "threads,eps_over_h,nu,points,bonds,steps,wall_s,cpu_s,bond_updates_per_s,bytes_per_bond,GB_per_s\n";
    for (const Row& r : rows)
      csv << threads << ',' << r.epsOverH << ',' << r.nu << ',' << r.points << ',' << r.bonds << ',' << r.steps << ','
          << r.seconds << ',' << r.cpu << ',' << r.updatesPerSecond << ',' << r.bytesPerBond << ',' << r.gbPerSecond
          << '\n';
  }
  return 0;
}
