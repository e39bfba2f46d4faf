// The command line of `peristep`: `info` within a terminal's width and `info NAME` in full, `--set
// name=value` in run, convergence and sample (the value reaches the results), `--threads N`.
#include <catch2/catch.hpp>

#include <sstream>

#include "host_test_support.hpp"
#include "terminal_text.hpp"

using namespace host_test;
using Catch::Matchers::Contains;

namespace {

ProcessResult cli(const TempDir& dir, std::vector<std::string> args) {
  args.insert(args.begin(), PERISTEP_HOST_BINARY);
  return runProcess(args, dir.path());
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

double doubleAttribute(hid_t object, const char* name) {
  const hid_t a = H5Aopen(object, name, H5P_DEFAULT);
  double v = -1;
  H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  return v;
}

// The `column` of a CSV file's rows, as numbers.
std::vector<double> csvColumn(const fs::path& file, const std::string& column) {
  const std::vector<std::string> rows = lines(readText(file));
  std::vector<double> values;
  if (rows.empty()) return values;
  std::size_t index = 0;
  {
    std::istringstream h(rows[0]);
    std::size_t k = 0;
    bool found = false;
    for (std::string key; std::getline(h, key, ','); ++k)
      if (key == column) index = k, found = true;
    REQUIRE(found);
  }
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::istringstream v(rows[r]);
    std::string cell;
    for (std::size_t k = 0; k <= index; ++k) std::getline(v, cell, ',');
    values.push_back(std::stod(cell));
  }
  return values;
}

const std::string kSmooth = PERISTEP_SOURCE_DIR "/scenes/smooth.toml";

}  // namespace

TEST_CASE("cli: peristep info fits 100 columns, one line per scene and variable", "[host][cli][info]") {
  TempDir dir;
  const ProcessResult r = cli(dir, {"info", "--fmu", PERISTEP_FMU});
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  const std::vector<std::string> all = lines(r.out);
  CHECK(all.size() > 100);
  for (const std::string& line : all) {
    INFO(line);
    CHECK(peristep::host::displayWidth(line) <= 100);
  }
  // A line per variable: the 1089 start values of a material map are summarized, not listed.
  const auto lineOf = [&](const std::string& start) {
    for (const std::string& line : all)
      if (line.rfind(start, 0) == 0) return line;
    return std::string();
  };
  CHECK_THAT(lineOf("  materialYoungsModulus[ny][nx] "), Contains("[1089 values]"));
  CHECK_THAT(lineOf("  poissonRatio "), Contains("Float64"));
  CHECK_THAT(lineOf("  glassCeramic "), Contains("glass-ceramic"));
  // The old form, the FMU as the argument, still works.
  CHECK(cli(dir, {"info", PERISTEP_FMU}).out == r.out);
}

TEST_CASE("cli: peristep info NAME shows one variable or scene in full", "[host][cli][info]") {
  TempDir dir;
  const ProcessResult e = cli(dir, {"info", "materialYoungsModulus"});
  INFO(e.err);
  REQUIRE(e.exitCode == 0);
  CHECK_THAT(e.out, Contains("materialYoungsModulus[ny][nx]"));
  CHECK_THAT(e.out, Contains("unit Pa"));
  CHECK_THAT(e.out, Contains("start (1089 values):"));
  std::size_t values = 0;
  std::istringstream words(e.out.substr(e.out.find("start (1089 values):") + 20));
  for (std::string word; words >> word && word != "description:";) ++values;
  CHECK(values == 1089);  // every start value, wrapped
  for (const std::string& line : lines(e.out)) CHECK(peristep::host::displayWidth(line) <= 100);

  const ProcessResult s = cli(dir, {"info", "scene"});
  REQUIRE(s.exitCode == 0);
  CHECK_THAT(s.out, Contains("items of PeriStep.Scene:"));
  CHECK_THAT(s.out, Contains("glassCeramic = 4: Pre-cracked glass-ceramic plate"));

  const ProcessResult g = cli(dir, {"info", "glassCeramic"});
  REQUIRE(g.exitCode == 0);
  CHECK_THAT(g.out, Contains("scene glassCeramic"));

  const ProcessResult unknown = cli(dir, {"info", "poisonRatio"});
  CHECK(unknown.exitCode == 2);
  CHECK_THAT(unknown.err, Contains("did you mean poissonRatio?"));
}

TEST_CASE("cli: run --set overrides and adds [parameters] values, read as the variable's type", "[host][cli][run]") {
  TempDir dir;
  const ProcessResult r = cli(dir, {"run", kSmooth, "--set", "nx=9", "--set", "ny=9", "--set", "poissonRatio=0.27",
                                         "--set", "linearSolver=sparseLU", "--set", "xi=[0.5]", "--out", "s.h5"});
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.out, Contains("wrote s.h5 (4 steps, 9 x 9 points)"));
  const hid_t f = openHdf5(dir / "s.h5");
  REQUIRE(f >= 0);
  const hid_t params = H5Gopen2(f, "/parameters", H5P_DEFAULT);
  CHECK(doubleAttribute(params, "nx") == 9.0);
  CHECK(doubleAttribute(params, "poissonRatio") == 0.27);
  H5Gclose(params);
  CHECK(readDataset(f, "/fields/ux").shape == std::vector<hsize_t>{4, 9, 9});
  H5Fclose(f);
  // The same run with xi = 0 (the file's start value): a different displacement, so xi was set.
  REQUIRE(cli(dir, {"run", kSmooth, "--set", "nx=9", "--set", "ny=9", "--set", "poissonRatio=0.27", "--out", "z.h5"})
              .exitCode == 0);
  const hid_t a = openHdf5(dir / "s.h5"), b = openHdf5(dir / "z.h5");
  CHECK(readDataset(a, "/fields/ux").values != readDataset(b, "/fields/ux").values);
  H5Fclose(a);
  H5Fclose(b);
}

TEST_CASE("cli: --set refuses unknown names, unsettable variables and values of the wrong type", "[host][cli]") {
  TempDir dir;
  const auto refused = [&](const std::string& set, const std::string& message) {
    const ProcessResult r = cli(dir, {"run", kSmooth, "--set", set, "--out", "x.h5"});
    INFO(set << ": " << r.err);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.err, Contains(message));
    CHECK_FALSE(fs::exists(dir / "x.h5"));
  };
  refused("nxx=9", "--set nxx=9: unknown variable");
  refused("nxx=9", "did you mean nx?");
  refused("nx=nine", "expected an integer for UInt64");
  refused("nx=-3", "expected a non-negative integer");
  refused("poissonRatio=0.3.1", "expected a finite number");
  refused("poissonRatio", "expected name=value");
  refused("scene=cracked", "unknown item \"cracked\" of PeriStep.Scene");
  refused("errorL2=0", "errorL2 is a continuous output and cannot be set");
  // Checked as a value in the file is: two values where the start value of nModes asks for one.
  const ProcessResult shape = cli(dir, {"run", kSmooth, "--set", "nModes=1", "--set", "xi=0.1, 0.2", "--out", "x.h5"});
  CHECK(shape.exitCode == 2);
  CHECK_THAT(shape.err, Contains("xi: has 2 values but its shape [nModes = 1] needs 1"));
}

TEST_CASE("cli: convergence --set changes every level, and nx and ny belong to the levels", "[host][cli][convergence]") {
  TempDir dir;
  writeText(dir / "c.toml", "[parameters]\nscene = \"smooth\"\n[convergence]\nlevels = [4, 8]\n");
  REQUIRE(cli(dir, {"convergence", "c.toml", "--out", "a.csv"}).exitCode == 0);
  const ProcessResult r = cli(dir, {"convergence", "c.toml", "--set", "poissonRatio=0.45", "--out", "b.csv"});
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  const std::vector<double> a = csvColumn(dir / "a.csv", "error_l2"), b = csvColumn(dir / "b.csv", "error_l2");
  REQUIRE(a.size() == 2);
  REQUIRE(b.size() == 2);
  CHECK(a[0] != b[0]);
  CHECK(a[1] != b[1]);

  const ProcessResult nx = cli(dir, {"convergence", "c.toml", "--set", "nx=9", "--out", "n.csv"});
  CHECK(nx.exitCode == 2);
  CHECK_THAT(nx.err, Contains("sets nx and ny from its [convergence] levels"));
}

TEST_CASE("cli: sample --set reaches every sample and is recorded in the study file", "[host][cli][sample]") {
  TempDir dir;
  const ProcessResult r = cli(dir, {"sample", PERISTEP_SOURCE_DIR "/scenes/smooth_sampling.toml", "--rule",
                                         "tensor", "--level", "2", "--set", "nx=9", "--set", "ny=9", "--out", "t.h5"});
  INFO(r.out << r.err);
  REQUIRE(r.exitCode == 0);
  const hid_t f = openHdf5(dir / "t.h5");
  REQUIRE(f >= 0);
  CHECK(readDataset(f, "/grid/x").shape == std::vector<hsize_t>{9, 9});
  CHECK(readDataset(f, "/level_2/samples/ux").shape == std::vector<hsize_t>{2, 9, 9});
  const hid_t set = H5Aopen(f, "set", H5P_DEFAULT);
  CHECK(set >= 0);
  if (set >= 0) H5Aclose(set);
  H5Fclose(f);
}

TEST_CASE("cli: --threads takes a positive count, before or after the subcommand", "[host][cli]") {
  TempDir dir;
  const std::vector<std::string> small{"--set", "nx=9", "--set", "ny=9"};
  auto args = [&](std::vector<std::string> head) {
    head.insert(head.end(), small.begin(), small.end());
    return head;
  };
  CHECK(cli(dir, args({"run", kSmooth, "--threads", "1", "--out", "one.h5"})).exitCode == 0);
  CHECK(fs::exists(dir / "one.h5"));
  CHECK(cli(dir, args({"--threads", "2", "run", kSmooth, "--out", "two.h5"})).exitCode == 0);
  CHECK(fs::exists(dir / "two.h5"));
  for (const char* bad : {"0", "-1", "two"}) {
    const ProcessResult r = cli(dir, args({"run", kSmooth, "--threads", bad, "--out", "bad.h5"}));
    INFO(bad << ": " << r.err);
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.err, Contains("--threads"));
    CHECK_FALSE(fs::exists(dir / "bad.h5"));
  }
}
