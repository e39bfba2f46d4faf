// Bad input ends `peristep` with one line on stderr and a non-zero exit code (2 for what the user
// can fix in a file or the command line, 1 when the component refuses), and never damages an
// earlier result file.
#include <catch2/catch.hpp>

#include "host_test_support.hpp"

using namespace host_test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

const std::string kEarlier = "results of an earlier run: must survive";

struct Failure {
  int exitCode;
  std::string err;
};

// Runs `peristep args...` in a directory holding `scene.toml` and an earlier out.h5 / out.xmf,
// checks the failure is one line and that the earlier files are untouched.
Failure failingRun(const std::vector<std::string>& args, const std::string& scene = "") {
  TempDir dir;
  if (!scene.empty()) writeText(dir / "scene.toml", scene);
  writeText(dir / "out.h5", kEarlier);
  writeText(dir / "out.xmf", kEarlier);
  std::vector<std::string> argv{PERISTEP_HOST_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  const ProcessResult r = runProcess(argv, dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  CHECK(r.exitCode != 0);
  CHECK(lineCount(r.err) == 1);
  CHECK_THAT(r.err, StartsWith("peristep: "));
  CHECK(readText(dir / "out.h5") == kEarlier);
  CHECK(readText(dir / "out.xmf") == kEarlier);
  CHECK_FALSE(fs::exists(dir / "out.partial.h5"));
  return {r.exitCode, r.err};
}

}  // namespace

TEST_CASE("errors: missing scene file", "[host][errors]") {
  const Failure f = failingRun({"run", "nothere.toml", "--fmu", PERISTEP_FMU, "--out", "out.h5"});
  CHECK(f.exitCode == 2);
  CHECK_THAT(f.err, Contains("nothere.toml: cannot open the scene file"));
}

TEST_CASE("errors: missing FMU", "[host][errors]") {
  const Failure f = failingRun({"run", "--fmu", "nothere.fmu", "--out", "out.h5"});
  CHECK(f.exitCode == 2);
  CHECK_THAT(f.err, Contains("nothere.fmu: no such FMU"));
}

TEST_CASE("errors: a file that is not an FMU", "[host][errors]") {
  const Failure f = failingRun({"run", "--fmu", "scene.toml", "--out", "out.h5"}, "not a zip archive\n");
  CHECK(f.exitCode == 2);
  CHECK_THAT(f.err, Contains("scene.toml: cannot open the FMU archive"));
}

TEST_CASE("errors: unknown variable in a scene", "[host][errors]") {
  const Failure f = failingRun({"run", "scene.toml", "--fmu", PERISTEP_FMU, "--out", "out.h5"},
                               "[parameters]\npoissonRatio = 0.3\npoisonRatio = 0.2\n");
  CHECK(f.exitCode == 2);
  CHECK_THAT(f.err, Contains("scene.toml:3: [parameters] poisonRatio: unknown variable"));
}

TEST_CASE("errors: malformed values in a scene", "[host][errors]") {
  SECTION("a string for a number") {
    const Failure f = failingRun({"run", "scene.toml", "--fmu", PERISTEP_FMU, "--out", "out.h5"},
                                 "[parameters]\nLx = \"one\"\n");
    CHECK(f.exitCode == 2);
    CHECK_THAT(f.err, Contains("scene.toml:2: [parameters] Lx: expected a number for Float64, got a string"));
  }
  SECTION("not TOML") {
    const Failure f = failingRun({"run", "scene.toml", "--fmu", PERISTEP_FMU, "--out", "out.h5"},
                                 "[parameters]\nLx = = 1\n");
    CHECK(f.exitCode == 2);
    CHECK_THAT(f.err, Contains("scene.toml:2: TOML syntax error"));
  }
  SECTION("an unknown enumeration item") {
    const Failure f = failingRun({"run", "scene.toml", "--fmu", PERISTEP_FMU, "--out", "out.h5"},
                                 "[parameters]\nscene = \"rough\"\n");
    CHECK(f.exitCode == 2);
    CHECK_THAT(f.err, Contains("expected one of: smooth, composite"));
  }
}

TEST_CASE("errors: the component refuses a value: its own message is shown", "[host][errors]") {
  const Failure f = failingRun({"run", "scene.toml", "--fmu", PERISTEP_FMU, "--out", "out.h5"},
                               "[parameters]\npoissonRatio = 0.5\n");
  CHECK(f.exitCode == 1);
  CHECK_THAT(f.err, Contains("returned fmi3Error: "));
  CHECK_THAT(f.err, Contains("oisson"));  // the component's message names the parameter
}

TEST_CASE("errors: command-line mistakes", "[host][errors]") {
  CHECK(failingRun({"frobnicate"}).exitCode == 2);
  CHECK(failingRun({"run", "--out"}).exitCode == 2);
  CHECK(failingRun({"convergence"}).exitCode == 2);
  const Failure noLevels = failingRun({"convergence", "scene.toml", "--fmu", PERISTEP_FMU}, "[parameters]\n");
  CHECK(noLevels.exitCode == 2);
  CHECK_THAT(noLevels.err, Contains("[convergence] levels: missing"));
}
