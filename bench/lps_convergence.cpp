// Refinement study of the quasi-static LPS solver against an exact solution (error against run time).
//
//   lps_convergence [--scene smooth|composite] [--nu 0.3] [--xi 0 [--xi2 0]] [--contrast 2]
//                   [--levels 8,16,32,64,128,256] [--delta-over-h 3] [--jitter 0]
//                   [--solver umfpack|umfpackAmd|sparseLU|bicgstabIlut] [--csv out.csv]
//
// Test 1 (smooth, 000 Sec. 4.1) runs on [-1/2,1/2]^2 with h = 1/level; Test 2 (composite, 000 Sec. 4.2)
// on [-pi/2,pi/2]^2 with h = pi/level. Per level it prints h, points, unknowns, L2 error, observed rate,
// the wall time of every phase and the peak resident memory.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "bench_cli.hpp"
#include "core/errors.hpp"
#include "core/memory.hpp"
#include "core/timer.hpp"
#include "scenes/manufactured.hpp"
#include "solvers/static_lps.hpp"

using namespace peristep;

namespace {

struct Options {
  std::string scene = "smooth", solver = "umfpack", csv;
  double nu = 0.3, xi = 0.0, xi2 = 0.0, contrast = 2.0, deltaOverH = 3.0, jitter = 0.0;
  std::vector<int> levels{8, 16, 32, 64, 128, 256};
};

// The options, or the exit code when the program should stop here (--help, or a parse error).
std::variant<Options, int> parse(int argc, char** argv) {
  Options o;
  CLI::App app{"lps_convergence: refinement study of the quasi-static LPS solver against an exact solution"};
  app.add_option("--scene", o.scene, "Test 1 (smooth) or Test 2 (composite)")
      ->capture_default_str()
      ->check(CLI::IsMember({"smooth", "composite"}));
  app.add_option("--nu", o.nu, "Poisson ratio")->capture_default_str();
  app.add_option("--xi", o.xi, "random coordinate xi (xi1 of the composite)")->capture_default_str();
  app.add_option("--xi2", o.xi2, "composite: second random coordinate")->capture_default_str();
  app.add_option("--contrast", o.contrast, "composite: modulus contrast")->capture_default_str();
  app.add_option("--levels", o.levels, "grid levels, comma separated")->delimiter(',')->capture_default_str();
  app.add_option("--delta-over-h", o.deltaOverH, "horizon delta/h")->capture_default_str();
  app.add_option("--jitter", o.jitter, "random displacement of the points, fraction of h")->capture_default_str();
  app.add_option("--solver", o.solver, "sparse solver")
      ->capture_default_str()
      ->check(CLI::IsMember(linearSolverNames()));
  app.add_option("--csv", o.csv, "write the table as CSV to this file");
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  return o;
}

}  // namespace

int main(int argc, char** argv) try {
  const std::variant<Options, int> parsed = parse(argc, argv);
  if (const int* code = std::get_if<int>(&parsed)) return *code;
  const Options& o = std::get<Options>(parsed);
  const bool smooth = o.scene == "smooth";
  std::unique_ptr<ElasticScene> scene;
  if (smooth) scene = std::make_unique<SmoothScene>(o.nu, o.xi);
  else scene = std::make_unique<CompositeScene>(o.nu, o.xi, o.xi2, o.contrast);
  const double side = smooth ? 1.0 : std::numbers::pi;

  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) throw InvalidInput("cannot write " + o.csv);
    csv << "h,points,unknowns,bonds,error_l2,rate,t_neighbours,t_weights,t_assembly,t_factorization,t_solve,"
           "t_total,peak_mb\n";
  }
  std::printf("# scene %s, nu = %g, delta/h = %g, jitter = %g h, solver %s\n", o.scene.c_str(), o.nu,
              o.deltaOverH, o.jitter, o.solver.c_str());
  std::printf("%10s %8s %9s %11s %6s %7s %7s %7s %7s %7s %8s %8s\n", "h", "points", "unknowns", "L2 error", "rate",
              "neigh", "weights", "assemb", "factor", "solve", "total s", "peak MB");
  double prevError = 0, prevH = 0;
  for (int level : o.levels) {
    resetPeakMemory();
    Stopwatch total;
    GridSpec grid;
    grid.nx = grid.ny = static_cast<std::size_t>(level) + 1;
    grid.Lx = grid.Ly = side;
    grid.deltaOverH = o.deltaOverH;
    grid.jitter = o.jitter;
    auto disc = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(grid));
    StaticLps lps(disc, *scene, linearSolverKind(o.solver));
    lps.solve();
    const double seconds = total.seconds();
    const double error = lps.errorL2(), h = disc->cloud.h;
    const double rate = prevError > 0 ? std::log(prevError / error) / std::log(prevH / h) : NAN;
    const double peakMb = static_cast<double>(peakMemoryBytes()) / 1048576.0;
    const auto& t = lps.times();
    std::printf("%10.3e %8zu %9lld %11.4e %6.2f %7.2f %7.2f %7.2f %7.2f %7.2f %8.2f %8.0f\n", h, disc->cloud.size(),
                static_cast<long long>(lps.unknowns()), error, rate, disc->neighbourSeconds, disc->weightSeconds,
                t.assembly, t.factorization, t.solve, seconds, peakMb);
    std::fflush(stdout);
    if (csv)
      csv << h << ',' << disc->cloud.size() << ',' << lps.unknowns() << ',' << lps.discretization().neighbours.bonds()
          << ',' << error << ',' << rate << ',' << disc->neighbourSeconds << ',' << disc->weightSeconds << ','
          << t.assembly << ',' << t.factorization << ',' << t.solve << ',' << seconds << ',' << peakMb << '\n';
    prevError = error;
    prevH = h;
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "lps_convergence: " << e.what() << '\n';
  return 1;
}
