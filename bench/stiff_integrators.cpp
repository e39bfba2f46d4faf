// Error against run time for the three time integrators on the stiff-inclusion plate
// (component/scenes/stiff_inclusions.hpp; modulus contrast 1e3 by default).
//
// How to run:  stiff_integrators [contrast] [csv]
// What it shows: for central difference (at fractions of its stability limit), ARKODE ERK and CVODE
// BDF (at several tolerances): steps, force evaluations (plus Jacobian-vector products), wall time
// and the relative L2 error of the displacement at the end time against a central-difference
// reference at a quarter of the stability limit (whose own error is estimated from half of it).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_cli.hpp"
#include "core/timer.hpp"
#include "scenes/stiff_inclusions.hpp"
#include "solvers/central_difference.hpp"

using namespace peristep;

namespace {

struct Run {
  std::string method, setting;
  IntegratorStats stats;
  double seconds = 0, error = 0;
  std::vector<double> u;
};

Run run(double contrast, const std::string& method, const IntegratorOptions& o, const std::string& setting) {
  StiffInclusionsSpec spec;
  spec.contrast = contrast;
  DynamicScene scene = makeStiffInclusions(spec);
  const Stopwatch clock;
  auto integrator = makeTimeIntegrator(method, *scene.problem, o);
  integrator->advanceTo(scene.endTime);
  Run r{method, setting, integrator->stats(), clock.seconds(), 0, {}};
  r.u.assign(integrator->displacement(), integrator->displacement() + scene.problem->dofs());
  return r;
}

double relativeError(const std::vector<double>& u, const std::vector<double>& ref) {
  double d = 0, n = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    d += (u[i] - ref[i]) * (u[i] - ref[i]);
    n += ref[i] * ref[i];
  }
  return std::sqrt(d / n);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"stiff_integrators: error against run time of the integrators on the stiff-inclusion plate"};
  double contrast = 1e3;
  std::string csvPath;
  app.add_option("contrast", contrast, "modulus contrast of the inclusions")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("csv", csvPath, "write the table as CSV to this file");
  if (const auto code = bench::parseArguments(app, argc, argv)) return *code;
  StiffInclusionsSpec spec;
  spec.contrast = contrast;
  DynamicScene probe = makeStiffInclusions(spec);
  const double limit = estimateStabilityLimit(*probe.problem).criticalStep;
  std::printf("stiff inclusions: contrast %g, %zu points, stability limit %.4e s, T = %g s\n", contrast,
              probe.cloud.size(), limit, probe.endTime);

  std::vector<Run> runs;
  const auto cd = [&](double fraction) {
    IntegratorOptions o;
    o.timeStep = fraction * limit;
    char setting[64];
    std::snprintf(setting, sizeof setting, "dt = %.2f x limit", fraction);
    runs.push_back(run(contrast, "centralDifference", o, setting));
  };
  cd(0.25);
  const Run reference = runs.back();
  cd(0.5);
  cd(0.95);
  // Absolute tolerances scaled with the relative one on the problem's scales: displacements ~1e-6 m,
  // velocities ~0.1 m/s.
  const auto tolerances = [](double rtol) {
    IntegratorOptions o;
    o.relativeTolerance = rtol;
    o.absoluteTolerance = rtol * 1e-6;
    o.velocityTolerance = rtol * 0.1;
    return o;
  };
  char setting[64];
  for (const double tol : {1e-4, 1e-6, 1e-8}) {
    std::snprintf(setting, sizeof setting, "rtol = %.0e", tol);
    runs.push_back(run(contrast, "arkodeErk", tolerances(tol), setting));
  }
  for (const double tol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    std::snprintf(setting, sizeof setting, "rtol = %.0e", tol);
    runs.push_back(run(contrast, "cvodeBdf", tolerances(tol), setting));
  }
  std::FILE* csv = csvPath.empty() ? nullptr : std::fopen(csvPath.c_str(), "w");
  if (csv) std::fprintf(csv, "method,setting,steps,rhs,jv,linear_iterations,factorizations,seconds,rel_error\n");
  std::printf("%-20s %-22s %8s %9s %9s %8s %6s %9s %11s\n", "method", "setting", "steps", "rhs", "J v", "lin it",
              "LDLT", "wall s", "rel error");
  for (Run& r : runs) {
    r.error = &r == &runs.front() ? 0.0 : relativeError(r.u, reference.u);
    std::printf("%-20s %-22s %8ld %9ld %9ld %8ld %6ld %9.3f %11.3e\n", r.method.c_str(), r.setting.c_str(), r.stats.steps,
                r.stats.rhsEvaluations, r.stats.jacobianProducts, r.stats.linearIterations, r.stats.preconditionerSetups,
                r.seconds, r.error);
    if (csv)
      std::fprintf(csv, "%s,%s,%ld,%ld,%ld,%ld,%ld,%.6f,%.6e\n", r.method.c_str(), r.setting.c_str(), r.stats.steps,
                   r.stats.rhsEvaluations, r.stats.jacobianProducts, r.stats.linearIterations,
                   r.stats.preconditionerSetups, r.seconds, r.error);
  }
  if (csv) std::fclose(csv);
  std::printf("(reference: central difference at 0.25 x limit; its error is about a quarter of the 0.5 x limit row)\n");
  return 0;
}
