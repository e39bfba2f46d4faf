// Multilevel Monte Carlo arithmetic (sampling/multilevel.hpp): Giles' optimal counts and the combined
// estimator, against hand calculations and a Monte Carlo check of the standard error.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "sampling/multilevel.hpp"

using namespace peristep::sampling;

TEST_CASE("level statistics: mean and unbiased variance", "[sampling][mlmc]") {
  const std::vector<double> v{1.0, 2.0, 4.0, 5.0};
  const LevelStatistics s = levelStatistics(v);
  CHECK(s.count == 4);
  CHECK(s.mean == Approx(3.0));
  CHECK(s.variance == Approx(10.0 / 3.0));  // (4 + 1 + 1 + 4) / 3
}

TEST_CASE("optimal counts reach the standard error at least cost", "[sampling][mlmc]") {
  // V = (4, 1, 0.25), C = (1, 4, 16): sqrt(V C) = 2 each, sum 6; N_l = sqrt(V_l / C_l) 6 / se^2.
  const std::vector<double> V{4.0, 1.0, 0.25}, C{1.0, 4.0, 16.0};
  const double se = 0.1;
  const auto n = optimalCounts(V, C, se, 2);
  CHECK(n == std::vector<std::size_t>{1200, 300, 75});
  double variance = 0;
  for (std::size_t l = 0; l < 3; ++l) variance += V[l] / static_cast<double>(n[l]);
  CHECK(variance <= se * se * (1 + 1e-12));
  // Another split of the same variance costs more: move samples from level 2 to level 0.
  const double cost = 1200 * 1.0 + 300 * 4.0 + 75 * 16.0;
  const double n0 = 4.0 / (se * se - 1.0 / 300 - 0.25 / 60);  // level 2 at 60 samples, level 0 makes up
  CHECK(n0 * 1.0 + 300 * 4.0 + 60 * 16.0 > cost);
  // A level without variance keeps the least count.
  CHECK(optimalCounts(std::vector<double>{4.0, 0.0}, std::vector<double>{1.0, 1.0}, 0.1, 5)[1] == 5);
  CHECK_THROWS(optimalCounts(V, C, 0.0, 2));
}

TEST_CASE("the combined standard error is the spread of the estimate", "[sampling][mlmc]") {
  // Y_0 ~ N(1, 1), Y_1 ~ N(0.1, 0.01) with 100 and 20 samples: se = sqrt(1/100 + 0.01/20).
  std::mt19937_64 rng(5);
  std::normal_distribution<double> z;
  std::vector<double> estimates, reported;
  for (int repeat = 0; repeat < 400; ++repeat) {
    std::vector<double> y0(100), y1(20);
    for (double& y : y0) y = 1.0 + z(rng);
    for (double& y : y1) y = 0.1 + 0.1 * z(rng);
    const std::vector<LevelStatistics> levels{levelStatistics(y0), levelStatistics(y1)};
    const MultilevelEstimate e = combine(levels);
    estimates.push_back(e.mean);
    reported.push_back(e.se);
  }
  const LevelStatistics spread = levelStatistics(estimates), se = levelStatistics(reported);
  const double exact = std::sqrt(1.0 / 100 + 0.01 / 20);
  CHECK(spread.mean == Approx(1.1).margin(4 * exact / std::sqrt(400.0)));
  CHECK(std::sqrt(spread.variance) == Approx(exact).epsilon(0.1));
  CHECK(se.mean == Approx(exact).epsilon(0.02));
}
