// `peristep sample --rule mlmc`: multilevel Monte Carlo over grids on 000's Test 3 (interface crack, two
// random coordinates), whose reaction depends smoothly on xi, so a Gauss rule of 8 x 8 points gives
// each grid's expectation to far below the Monte Carlo error: the known answer the estimator must hit.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>

#include "host_test_support.hpp"

using namespace host_test;
using Catch::Matchers::Contains;

namespace {

ProcessResult sample(const fs::path& dir, std::vector<std::string> args) {
  args.insert(args.begin(), {PERISTEP_HOST_BINARY, "sample"});
  args.insert(args.end(), {"--fmu", PERISTEP_FMU});
  return runProcess(args, dir);
}

// Rows of a CSV as column name -> number.
std::vector<std::map<std::string, double>> readCsv(const fs::path& file) {
  std::istringstream in(readText(file));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::istringstream h(line); std::getline(h, line, ',');) names.push_back(line);
  std::vector<std::map<std::string, double>> rows;
  for (std::string row; std::getline(in, row);) {
    std::map<std::string, double> r;
    std::istringstream s(row);
    std::size_t k = 0;
    for (std::string c; std::getline(s, c, ','); ++k) r[names.at(k)] = c.empty() ? NAN : std::strtod(c.c_str(), nullptr);
    rows.push_back(r);
  }
  return rows;
}

const std::vector<std::string> kMultilevel{"t3.toml", "--rule", "mlmc", "--grids", "3", "--quantity", "reactionTopY",
                                           "--se", "0.005", "--out", "ml.h5"};

}  // namespace

TEST_CASE("mlmc: the estimate of Test 3's reaction meets the finest grid's expectation within its standard error",
          "[host][sample][mlmc]") {
  TempDir dir;
  // E[Q] on each grid by the 8 x 8 Gauss rule.
  std::vector<double> exact;
  for (int n : {9, 17, 33}) {
    writeText(dir / "g.toml", sceneOnGrid("interface_crack_sampling.toml", n));
    const ProcessResult g = sample(dir.path(), {"g.toml", "--rule", "tensor", "--levels", "8", "--out", "g" + std::to_string(n) + ".h5"});
    REQUIRE(g.exitCode == 0);
    exact.push_back(readCsv(dir / ("g" + std::to_string(n) + ".csv")).back().at("mean_reactionTopY"));
  }
  writeText(dir / "t3.toml", sceneOnGrid("interface_crack_sampling.toml", 33));
  const ProcessResult r = sample(dir.path(), kMultilevel);
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  const auto summary = readCsv(dir / "ml_summary.csv").at(0);
  const auto levels = readCsv(dir / "ml.csv");
  REQUIRE(levels.size() == 3);
  const double se = summary.at("se");
  CHECK(se <= summary.at("target_se") * (1 + 1e-12));
  CHECK(summary.at("target_se") == Approx(0.005 * std::abs(summary.at("estimate"))));
  CHECK(std::abs(summary.at("estimate") - exact[2]) < 3 * se);
  // Each level's mean correction against the difference of the grids' expectations.
  for (std::size_t l = 0; l < 3; ++l) {
    INFO("level " << l);
    CHECK(levels[l].at("nx") == (l == 0 ? 9 : l == 1 ? 17 : 33));
    const double expected = exact[l] - (l > 0 ? exact[l - 1] : 0.0);
    CHECK(std::abs(levels[l].at("mean_Y") - expected) < 4 * levels[l].at("se_Y"));
  }
  // The corrections shrink, so the coarse level takes the most samples (Giles' allocation).
  CHECK(levels[0].at("var_Y") > levels[2].at("var_Y"));
  CHECK(levels[0].at("pairs") > levels[2].at("pairs"));

  // A restart finds every sample in the store and writes the same files.
  const std::string csv = readText(dir / "ml.csv"), summaryText = readText(dir / "ml_summary.csv");
  const ProcessResult again = sample(dir.path(), kMultilevel);
  REQUIRE(again.exitCode == 0);
  CHECK_THAT(again.out, Contains("0 computed by this run"));
  CHECK(readText(dir / "ml.csv") == csv);
  CHECK(readText(dir / "ml_summary.csv") == summaryText);
}

TEST_CASE("mlmc: the reported standard error is the spread of the estimate over seeds", "[host][sample][mlmc]") {
  TempDir dir;
  writeText(dir / "t3.toml", sceneOnGrid("interface_crack_sampling.toml", 17));
  std::vector<double> estimates, reported;
  for (int seed = 1; seed <= 10; ++seed) {
    const std::string out = "s" + std::to_string(seed) + ".h5";
    const ProcessResult r = sample(dir.path(), {"t3.toml", "--rule", "mlmc", "--grids", "2", "--quantity", "reactionTopY",
                                                "--se", "0.01", "--seed", std::to_string(1000 * seed), "--out", out});
    REQUIRE(r.exitCode == 0);
    const auto s = readCsv(dir / ("s" + std::to_string(seed) + "_summary.csv")).at(0);
    estimates.push_back(s.at("estimate"));
    reported.push_back(s.at("se"));
  }
  double mean = 0, meanSe = 0, spread = 0;
  for (std::size_t k = 0; k < estimates.size(); ++k) mean += estimates[k] / 10, meanSe += reported[k] / 10;
  for (double e : estimates) spread += (e - mean) * (e - mean) / 9;
  spread = std::sqrt(spread);
  INFO("spread " << spread << ", mean reported se " << meanSe);
  CHECK(spread > 0.5 * meanSe);
  CHECK(spread < 2.0 * meanSe);
}

TEST_CASE("mlmc: grids that do not halve and options of other rules are refused", "[host][sample][mlmc]") {
  TempDir dir;
  writeText(dir / "t3.toml", sceneOnGrid("interface_crack_sampling.toml", 31));
  ProcessResult r = sample(dir.path(), {"t3.toml", "--rule", "mlmc", "--grids", "3", "--quantity", "reactionTopY"});
  CHECK(r.exitCode == 2);
  CHECK_THAT(r.err, Contains("nx - 1 = 30 must be a multiple of 4"));
  r = sample(dir.path(), {"t3.toml", "--rule", "mlmc", "--samples", "4"});
  CHECK(r.exitCode == 2);
  CHECK_THAT(r.err, Contains("--rule mlmc chooses its own sample counts"));
  writeText(dir / "t3.toml", sceneOnGrid("interface_crack_sampling.toml", 33));
  r = sample(dir.path(), {"t3.toml", "--rule", "mlmc", "--quantity", "noSuchOutput", "--pilot", "2"});
  CHECK(r.exitCode == 2);
  CHECK_THAT(r.err, Contains("'noSuchOutput' is not a scalar Float64 output"));
}
