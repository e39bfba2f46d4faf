// Refinement study of Test 3 (000 Sec. 4.3): LPS with a fixed interface crack against the exact
// near-tip field, one sample xi = (xi1, xi2).
//
//   test3_convergence [--nu 0.3] [--xi1 0] [--xi2 0] [--levels 16,32,64,128] [--csv out.csv]
//
// Per level (h = pi/level) it prints points, unknowns, the L2 error of 000 Sec. 4.3, the observed rate,
// the wall time (set-up: cloud, neighbours, weights, assembly; solve: factorization and solve) and the
// peak resident memory.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "bench_cli.hpp"
#include "core/errors.hpp"
#include "core/memory.hpp"
#include "core/timer.hpp"
#include "scenes/interface_crack.hpp"

using namespace peristep;

namespace {

struct Options {
  double nu = 0.3, xi1 = 0.0, xi2 = 0.0;
  std::vector<int> levels{16, 32, 64, 128};
  std::string csv;
};

// The options, or the exit code when the program should stop here (--help, or a parse error).
std::variant<Options, int> parse(int argc, char** argv) {
  Options o;
  CLI::App app{"test3_convergence: refinement study of Test 3 (000 Sec. 4.3) against the exact near-tip field"};
  app.add_option("--nu", o.nu, "Poisson ratio")->capture_default_str();
  app.add_option("--xi1", o.xi1, "random coordinate xi1")->capture_default_str();
  app.add_option("--xi2", o.xi2, "random coordinate xi2")->capture_default_str();
  app.add_option("--levels", o.levels, "grid levels (h = pi/level), comma separated")->delimiter(',')->capture_default_str();
  app.add_option("--csv", o.csv, "write the table as CSV to this file");
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  return o;
}

}  // namespace

int main(int argc, char** argv) try {
  const std::variant<Options, int> parsed = parse(argc, argv);
  if (const int* code = std::get_if<int>(&parsed)) return *code;
  const Options& o = std::get<Options>(parsed);
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) throw InvalidInput("cannot write " + o.csv);
    csv << "h,points,unknowns,error_l2,rate,t_setup,t_solve,t_total,peak_mb\n";
  }
  std::printf("# Test 3, nu = %g, xi = (%g, %g), delta = 3h\n", o.nu, o.xi1, o.xi2);
  std::printf("%10s %8s %9s %11s %6s %8s %8s %8s %8s\n", "h", "points", "unknowns", "L2 error", "rate", "setup s",
              "solve s", "total s", "peak MB");
  double prevError = 0;
  for (int level : o.levels) {
    resetPeakMemory();
    Stopwatch clock;
    GridSpec g;
    g.nx = g.ny = static_cast<std::size_t>(level) + 1;
    g.Lx = g.Ly = std::numbers::pi;
    InterfaceCrackScene scene(g, o.nu, o.xi1, o.xi2);
    const double setup = clock.lap();
    scene.solve();
    const double solve = clock.lap();
    const double error = scene.errorL2();
    const double rate = prevError > 0 ? std::log2(prevError / error) : NAN;
    const double peakMb = static_cast<double>(peakMemoryBytes()) / 1048576.0;
    const auto& d = scene.solver().discretization();
    std::printf("%10.3e %8zu %9lld %11.4e %6.2f %8.2f %8.2f %8.2f %8.0f\n", d.cloud.h, d.cloud.size(),
                static_cast<long long>(d.dofs.size), error, rate, setup, solve, setup + solve, peakMb);
    std::fflush(stdout);
    if (csv)
      csv << d.cloud.h << ',' << d.cloud.size() << ',' << d.dofs.size << ',' << error << ',' << rate << ',' << setup
          << ',' << solve << ',' << setup + solve << ',' << peakMb << '\n';
    prevError = error;
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "test3_convergence: " << e.what() << '\n';
  return 1;
}
