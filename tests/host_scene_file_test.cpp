// Scene files name variables of the model description; every mistake is a one-line message that
// names the file, the line, the key and the problem.
#include <catch2/catch.hpp>

#include <cmath>

#include "host_errors.hpp"
#include "load_schedule.hpp"
#include "scene_file.hpp"

using namespace peristep::host;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

const ModelDescription& model() {
  static const ModelDescription md = readModelDescription(PERISTEP_HOST_TEST_DATA "/modelDescription.xml");
  return md;
}

Scene parse(const std::string& text) { return parseScene(text, "scene.toml", model()); }

// The message of the InputError that parsing `text` throws (fails the test if it does not throw).
std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no InputError for:\n" << text);
  return {};
}

template <class T>
const std::vector<T>& valuesOf(const Scene& s, const std::string& name) {
  const Setting* setting = s.setting(name);
  REQUIRE(setting);
  return std::get<std::vector<T>>(setting->values);
}

}  // namespace

TEST_CASE("scene: parameters of every kind", "[host][scene]") {
  const Scene s = parse(R"(
[parameters]
scene = "composite"
Lx = 2          # an integer is a fine Float64
poissonRatio = 0.25
seed = 7
smallInt = -5
flag = true
nx = 17
xi = [0.5, -1.5]
pair = [3.0, 4.0]
)");
  CHECK(valuesOf<std::int64_t>(s, "scene") == std::vector<std::int64_t>{2});
  CHECK(valuesOf<double>(s, "Lx") == std::vector<double>{2.0});
  CHECK(valuesOf<double>(s, "poissonRatio") == std::vector<double>{0.25});
  CHECK(valuesOf<std::uint64_t>(s, "seed") == std::vector<std::uint64_t>{7});
  CHECK(valuesOf<std::int64_t>(s, "smallInt") == std::vector<std::int64_t>{-5});
  CHECK(valuesOf<bool>(s, "flag") == std::vector<bool>{true});
  CHECK(valuesOf<double>(s, "xi") == std::vector<double>{0.5, -1.5});
  // xi's length sets its structural dimension when the scene does not.
  CHECK(valuesOf<std::uint64_t>(s, "nModes") == std::vector<std::uint64_t>{2});
  CHECK(s.setting("nModes")->variable.causality == Causality::StructuralParameter);
  CHECK(describeValues(*s.setting("scene"), model()) == "composite");
  CHECK(describeValues(*s.setting("xi"), model()) == "[0.5, -1.5]");
}

TEST_CASE("scene: loading defaults come from the DefaultExperiment", "[host][scene]") {
  const Scene s = parse("");
  CHECK_FALSE(s.loading.input.has_value());
  CHECK(s.loading.startTime == 0.0);
  CHECK(s.loading.stopTime == 2.0);
  CHECK(s.loading.steps == 4);  // (2 - 0) / 0.5
  CHECK(s.parameters.empty());
  CHECK(s.levels.empty());
  CHECK(s.outputFile.empty());
}

TEST_CASE("scene: a ramped input, output files and levels", "[host][scene]") {
  const Scene s = parse(R"(
[loading]
input = "loadFactor"
from = 0.5
to = 2.5
steps = 8
startTime = 1.0
stopTime = 3.0

[output]
file = "out.h5"
csv = "study.csv"

[convergence]
levels = [4, 8, 16]
)");
  REQUIRE(s.loading.input.has_value());
  CHECK(s.loading.input->valueReference == 30);
  CHECK(s.loading.from == 0.5);
  CHECK(s.loading.to == 2.5);
  CHECK(s.loading.steps == 8);
  CHECK(s.loading.startTime == 1.0);
  CHECK(s.loading.stopTime == 3.0);
  CHECK(s.outputFile == "out.h5");
  CHECK(s.csvFile == "study.csv");
  CHECK(s.levels == std::vector<std::uint64_t>{4, 8, 16});
}

TEST_CASE("scene: the load schedule ramps the input and ends exactly on stopTime", "[host][scene]") {
  Loading l;
  l.from = 0.0, l.to = 1.0, l.steps = 3, l.startTime = 0.0, l.stopTime = 0.3;
  const auto schedule = loadSchedule(l);
  REQUIRE(schedule.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(schedule[k].index == k + 1);
    CHECK(schedule[k].time == Approx(0.1 * static_cast<double>(k)).margin(1e-15));
    CHECK(schedule[k].input == Approx(static_cast<double>(k + 1) / 3.0));
  }
  // The steps tile [start, stop] without a gap, and the last lands on the end values exactly.
  for (std::size_t k = 0; k + 1 < 3; ++k) CHECK(schedule[k].time + schedule[k].stepSize == schedule[k + 1].time);
  CHECK(schedule.back().time + schedule.back().stepSize == 0.3);
  CHECK(schedule.back().input == 1.0);
}

TEST_CASE("scene: every error is one line with file, line, table and key", "[host][scene]") {
  const std::string e = errorOf("[parameters]\npoisonRatio = 0.3\n");
  CHECK_THAT(e, StartsWith("scene.toml:2: [parameters] poisonRatio: unknown variable"));
  CHECK_THAT(e, Contains("did you mean poissonRatio?"));
  CHECK(e.find('\n') == std::string::npos);
}

TEST_CASE("scene: wrong types and malformed values", "[host][scene]") {
  CHECK_THAT(errorOf("[parameters]\npoissonRatio = \"0.3\"\n"),
             Contains("[parameters] poissonRatio: expected a number for Float64, got a string"));
  CHECK_THAT(errorOf("[parameters]\nnx = 3.5\n"), Contains("nx: expected a non-negative integer for UInt64"));
  CHECK_THAT(errorOf("[parameters]\nseed = -1\n"), Contains("seed: -1 is out of range for UInt64"));
  CHECK_THAT(errorOf("[parameters]\nsmallInt = 3000000000\n"), Contains("out of range for Int32"));
  CHECK_THAT(errorOf("[parameters]\nflag = 1\n"), Contains("expected true or false"));
  CHECK_THAT(errorOf("[parameters]\nscene = \"rough\"\n"),
             Contains("unknown item \"rough\" of Test.Scene (expected one of: smooth, composite)"));
  CHECK_THAT(errorOf("[parameters]\nscene = 1\n"), Contains("expected an item name"));
  CHECK_THAT(errorOf("[parameters]\nxi = 0.5\n"), Contains("xi: is an array variable"));
  CHECK_THAT(errorOf("[parameters]\nLx = [1.0]\n"), Contains("Lx: is a scalar Float64, got an array"));
  CHECK_THAT(errorOf("[parameters]\nxi = []\n"), Contains("xi: empty array"));
  CHECK_THAT(errorOf("[parameters]\nxi = [1.0, \"a\"]\n"), Contains("expected a number"));
  CHECK_THAT(errorOf("[parameters]\nnModes = 3\nxi = [1.0, 2.0]\n"),
             Contains("xi: has 2 values but its shape [nModes = 3] needs 3"));
  CHECK_THAT(errorOf("[parameters]\npair = [1.0]\n"), Contains("pair: has 1 values but its shape [2] needs 2"));
  CHECK_THAT(errorOf("[parameters]\nx = [1.0]\n"), Contains("x: is a fixed calculatedParameter and cannot be set"));
  CHECK_THAT(errorOf("[parameters]\nerrorL2 = 0.0\n"), Contains("cannot be set"));
  CHECK_THAT(errorOf("[parameters]\nLx = 1.0\nLx = 2.0\n"), StartsWith("scene.toml:3: TOML syntax error"));
  CHECK_THAT(errorOf("[parameters\n"), StartsWith("scene.toml:1: TOML syntax error"));
}

TEST_CASE("scene: unknown tables and keys, bad loading and levels", "[host][scene]") {
  CHECK_THAT(errorOf("[paramaters]\n"), Contains("[top level] paramaters: unknown key"));
  CHECK_THAT(errorOf("title = 1\n"), Contains("expected a table [title]"));
  CHECK_THAT(errorOf("[output]\nfile = 3\n"), Contains("[output] file: expected a string"));
  CHECK_THAT(errorOf("[output]\nfolder = \"x\"\n"), Contains("[output] folder: unknown key (expected one of: file, csv, results)"));
  CHECK_THAT(errorOf("[loading]\ninput = \"loadFctor\"\nfrom = 0\nto = 1\n"),
             Contains("[loading] input: unknown variable \"loadFctor\" (did you mean loadFactor?)"));
  CHECK_THAT(errorOf("[loading]\ninput = \"Lx\"\nfrom = 0\nto = 1\n"), Contains("Lx is not a scalar floating-point input"));
  CHECK_THAT(errorOf("[loading]\ninput = \"loadFactor\"\nto = 1\n"), Contains("[loading] from: missing"));
  CHECK_THAT(errorOf("[loading]\nfrom = 0\n"), Contains("[loading] from: needs input"));
  CHECK_THAT(errorOf("[loading]\nsteps = 0\n"), Contains("[loading] steps: expected a positive integer"));
  CHECK_THAT(errorOf("[loading]\nstartTime = 1.0\nstopTime = 1.0\n"), Contains("must be greater than startTime"));
  CHECK_THAT(errorOf("[loading]\ninput = \"loadFactor\"\nfrom = nan\nto = 1\n"), Contains("[loading] from: must be finite"));
  CHECK_THAT(errorOf("[convergence]\nlevels = [8, 8]\n"), Contains("must increase strictly"));
  CHECK_THAT(errorOf("[convergence]\nlevels = [0]\n"), Contains("expected positive integers"));
  CHECK_THAT(errorOf("[convergence]\n"), Contains("[convergence] levels: missing"));
}

TEST_CASE("scene: missing file", "[host][scene]") {
  REQUIRE_THROWS_WITH(readScene("/nonexistent/scene.toml", model()),
                      "/nonexistent/scene.toml: cannot open the scene file");
}

TEST_CASE("scene: [output] results names scalar outputs a sample study is about", "[host][scene]") {
  const Scene s = parse("[output]\nresults = [\"errorL2\"]\n");
  CHECK(s.results == std::vector<std::string>{"errorL2"});
  CHECK(parse("[output]\nfile = \"a.h5\"\n").results.empty());
  CHECK_THAT(errorOf("[output]\nresults = [\"errorL3\"]\n"), Contains("[output] results: \"errorL3\" is not a scalar Float64 output (did you mean errorL2?)"));
  CHECK_THAT(errorOf("[output]\nresults = [\"ux\"]\n"), Contains("\"ux\" is not a scalar Float64 output"));
  CHECK_THAT(errorOf("[output]\nresults = [\"nx\"]\n"), Contains("is not a scalar Float64 output"));
  CHECK_THAT(errorOf("[output]\nresults = \"errorL2\"\n"), Contains("expected an array of output names"));
}
