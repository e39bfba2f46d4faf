// KL field eigenpairs (random/kl_field.hpp): wall time of the dense and the randomized solver on an
// n x n grid of the unit square, and how far the randomized eigenvalues are from the dense ones.
//
//   kl_modes [--sides 32,50,100] [--dense-up-to 2500] [--kernel exponential|gaussian] [--l 0.2] [--modes 20]
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "core/timer.hpp"
#include "random/kl_field.hpp"

using namespace peristep;

int main(int argc, char** argv) try {
  std::vector<std::size_t> sides{32, 50, 100};
  std::size_t denseUpTo = 2500;
  KlSpec spec;
  spec.correlationLength = 0.2;
  spec.standardDeviation = 1.0;
  spec.modes = 20;
  std::string kernel = "exponential";
  CLI::App app{"kl_modes: dense against randomized eigenpairs of the KL field"};
  app.add_option("--sides", sides, "grid points per side, comma separated")->delimiter(',')->capture_default_str();
  app.add_option("--dense-up-to", denseUpTo, "run the dense solver up to this many points")->capture_default_str();
  app.add_option("--kernel", kernel, "covariance kernel")
      ->capture_default_str()
      ->check(CLI::IsMember(optionNames(kCovarianceOptions)));
  app.add_option("--l", spec.correlationLength, "correlation length")->capture_default_str();
  app.add_option("--modes", spec.modes, "number of modes")->capture_default_str();
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  spec.kind = optionKind(kCovarianceOptions, kernel, "covariance kernel");
  std::printf("# KL, %s kernel, l = %g, k = %zu, randomized p = %zu, q = %zu\n", kernel.c_str(),
              spec.correlationLength, spec.modes, spec.oversampling, spec.powerIterations);
  std::printf("%7s %9s %12s %10s %14s\n", "points", "dense s", "randomized s", "retained", "max rel diff");
  for (std::size_t side : sides) {
    const double h = 1.0 / static_cast<double>(side);
    std::vector<double> x, y;
    for (std::size_t j = 0; j < side; ++j)
      for (std::size_t i = 0; i < side; ++i) {
        x.push_back((static_cast<double>(i) + 0.5) * h);
        y.push_back((static_cast<double>(j) + 0.5) * h);
      }
    spec.solver = KlSolver::Randomized;
    Stopwatch clock;
    const KlField fast(x, y, h, spec);
    const double fastSeconds = clock.lap();
    if (x.size() <= denseUpTo) {
      spec.solver = KlSolver::Dense;
      clock.lap();
      const KlField dense(x, y, h, spec);
      const double denseSeconds = clock.lap();
      const double diff =
          ((fast.eigenvalues() - dense.eigenvalues()).array() / dense.eigenvalues().array()).abs().maxCoeff();
      std::printf("%7zu %9.2f %12.2f %10.4f %14.2e\n", x.size(), denseSeconds, fastSeconds,
                  dense.retainedVarianceFraction(), diff);
    } else {
      std::printf("%7zu %9s %12.2f %10.4f %14s\n", x.size(), "-", fastSeconds, fast.retainedVarianceFraction(), "-");
    }
    std::fflush(stdout);
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "kl_modes: " << e.what() << '\n';
  return 1;
}
