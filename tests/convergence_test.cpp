// Spatial convergence to the local limit (000 Sec. 4, DESIGN Section 6): O(delta^2) for Test 1,
// O(delta) for Test 2, and the stiff and extreme cases of DESIGN Section 7. The full studies to
// h = 1/256 are in bench/lps_convergence.
#include <catch2/catch.hpp>
#include <numbers>

#include "lps_test_support.hpp"
#include "scenes/manufactured.hpp"

using namespace peristep;
using namespace peristep::testing;

namespace {

std::vector<double> smoothErrors(double nu, double xi, std::vector<int> levels, double deltaOverH = 3.0,
                                 double jitter = 0.0) {
  const SmoothScene scene(nu, xi);
  std::vector<double> e;
  for (int level : levels) e.push_back(levelError(scene, squareGrid(level, 1.0, deltaOverH, jitter)));
  return e;
}

std::vector<double> compositeErrors(double nu, double contrast, std::vector<int> levels) {
  const CompositeScene scene(nu, 0.0, 0.0, contrast);
  std::vector<double> e;
  for (int level : levels) e.push_back(levelError(scene, squareGrid(level, std::numbers::pi)));
  return e;
}

}  // namespace

TEST_CASE("Test 1 converges at second order", "[convergence][test1]") {
  const double nu = GENERATE(0.3, 0.495);
  const double xi = GENERATE(0.0, 0.1);
  const auto e = smoothErrors(nu, xi, {16, 32, 64});
  const auto r = halvingRates(e);
  INFO("nu " << nu << " xi " << xi << ": errors " << e[0] << " " << e[1] << " " << e[2] << ", rates " << r[0] << " "
             << r[1]);
  for (double rate : r) CHECK(rate >= 1.8);
}

TEST_CASE("Test 2 converges at first order", "[convergence][test2]") {
  const double nu = GENERATE(0.3, 0.495);
  const auto e = compositeErrors(nu, 2.0, {8, 16, 32, 64});
  const auto r = halvingRates(e);
  INFO("nu " << nu << ": rates " << r[0] << " " << r[1] << " " << r[2]);
  for (double rate : r) CHECK(rate >= 0.85);
}

TEST_CASE("stiff: nu = 0.4999 solves and its error decreases under refinement", "[convergence][stiff]") {
  const auto e = smoothErrors(0.4999, 0.0, {16, 32, 64});
  INFO("errors " << e[0] << " " << e[1] << " " << e[2]);
  for (double err : e) REQUIRE(std::isfinite(err));
  CHECK(e[1] < e[0]);
  CHECK(e[2] < e[1]);
}

TEST_CASE("stiff: a modulus contrast of 1e6 solves and its error decreases", "[convergence][stiff]") {
  const auto e = compositeErrors(0.3, 1e6, {8, 16, 32, 64});
  const auto r = halvingRates(e);
  INFO("rates " << r[0] << " " << r[1] << " " << r[2]);
  for (double rate : r) CHECK(rate > 0.5);
}

TEST_CASE("delta/h from 2 to 5 all converge at second order", "[convergence][extreme]") {
  const double ratio = GENERATE(2.0, 3.0, 4.0, 5.0);
  const auto r = halvingRates(smoothErrors(0.3, 0.0, {16, 32, 64}, ratio));
  INFO("delta/h " << ratio << ": rates " << r[0] << " " << r[1]);
  for (double rate : r) CHECK(rate >= 1.8);
}

TEST_CASE("a jittered cloud (+-0.2 h) keeps a Test 1 rate >= 1.5", "[convergence][extreme]") {
  const auto r = halvingRates(smoothErrors(0.3, 0.0, {16, 32, 64}, 3.0, 0.2));
  INFO("rates " << r[0] << " " << r[1]);
  for (double rate : r) CHECK(rate >= 1.5);
}

TEST_CASE("all linear solvers agree on Test 1", "[solvers]") {
  const SmoothScene scene(0.3, 0.0);
  const double reference = levelError(scene, squareGrid(16, 1.0), LinearSolverKind::Umfpack);
  for (const auto& option : kLinearSolverOptions) {
    INFO(option.name);
    CHECK(levelError(scene, squareGrid(16, 1.0), option.kind) == Approx(reference).epsilon(1e-6));
  }
}
