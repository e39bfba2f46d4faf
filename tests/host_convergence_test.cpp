// `peristep convergence scenes/smooth_convergence.toml`: Test 1 converges at second order in L2
// (000 Sec. 4.1: O(delta^2) with delta = 3h), read from the CSV the command writes.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "host_test_support.hpp"

using namespace host_test;
using Catch::Matchers::Contains;

namespace {

struct Row {
  double level, h, error, rate, wall, memory;
};

std::vector<Row> readCsv(const fs::path& file) {
  std::istringstream in(readText(file));
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "level,nx,ny,h,points,error_l2,rate,wall_s,peak_rss_mb");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    REQUIRE(v.size() == 9);
    rows.push_back({v[0], v[3], v[5], v[6], v[7], v[8]});
  }
  return rows;
}

}  // namespace

TEST_CASE("peristep convergence: Test 1 at second order between levels 16, 32, 64", "[host][convergence]") {
  TempDir dir;
  const ProcessResult r = runProcess({PERISTEP_HOST_BINARY, "convergence", PERISTEP_SOURCE_DIR "/scenes/smooth_convergence.toml",
                                      "--fmu", PERISTEP_FMU, "--out", "study.csv"},
                                     dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.out, Contains("L2 error"));
  CHECK_THAT(r.out, Contains("wrote study.csv"));

  const std::vector<Row> rows = readCsv(dir / "study.csv");
  REQUIRE(rows.size() == 4);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    CHECK(rows[k].level == std::vector<double>{8, 16, 32, 64}[k]);
    CHECK(rows[k].h == Approx(1.0 / rows[k].level));
    CHECK(std::isfinite(rows[k].error));
    CHECK(rows[k].error > 0);
    CHECK(rows[k].wall > 0);
    CHECK(rows[k].memory > 1);  // megabytes of the child that ran the level
  }
  CHECK(std::isnan(rows[0].rate));
  for (std::size_t k = 2; k < rows.size(); ++k) {
    INFO("level " << rows[k].level);
    // The CSV's rate is the one computed from its own errors and spacings.
    CHECK(rows[k].rate == Approx(std::log(rows[k - 1].error / rows[k].error) / std::log(2.0)).epsilon(1e-9));
    CHECK(rows[k].rate >= 1.8);
  }
  CHECK(rows[3].memory > rows[0].memory);  // the finest level needs the most

  if (std::getenv("PATH") && std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    const std::string png = readText(dir / "study.png");
    REQUIRE(png.size() > 8);
    CHECK(png.substr(1, 3) == "PNG");
  }
}
