// Progress inside a step: the component's logProgress messages reach the host's listener
// while fmi3DoStep runs, so the bar can show the sub-iterations and broken bonds of a running crack.
#include <catch2/catch.hpp>
#include <map>
#include <string>

#include "commands/opened_fmu.hpp"
#include "host_test_support.hpp"
#include "fmu_loader.hpp"
#include "simulation.hpp"

using namespace peristep::host;
using namespace host_test;

TEST_CASE("a glass-ceramic step reports its sub-iterations and broken bonds while it runs", "[progress]") {
  const OpenedFmu fmu(PERISTEP_FMU);
  // The small plate of the picture test, opened until the crack runs.
  const TempDir dir;
  std::string text = readText(fs::path(PERISTEP_HOST_TEST_DATA) / "glass_ceramic_small.toml");
  text.replace(text.find("to = 0.05e-6"), 12, "to = 0.6e-6");
  writeText(dir.path() / "cracking.toml", text);
  const Scene scene = loadScene((dir.path() / "cracking.toml").string(), fmu.md);
  const FmuLibrary library(fmu.archive.binaryFile(fmu.md.coSimulationIdentifier));
  FmuInstance::Options options;
  options.resourcePath = fmu.archive.resourcePath();
  std::map<std::string, std::uint64_t> last;  // phase -> last count reported during the current step
  bool inStep = false;
  std::uint64_t reportsInSteps = 0;
  options.progress = [&](const std::string& phase, std::uint64_t done, std::uint64_t) {
    last[phase] = done;
    if (inStep) ++reportsInSteps;
  };
  Simulation simulation(library, fmu.md, scene, options);
  CHECK(last.count("setUp") == 1);  // initialization reports too

  const double preCrack = simulation.readScalar("brokenBonds");  // the pre-crack's pairs
  double broken = preCrack;
  for (const Increment& inc : simulation.schedule()) {
    if (!simulation.mayContinue()) break;  // the crack has crossed the plate
    last.clear();
    inStep = true;
    simulation.step(inc);
    inStep = false;
    const double total = simulation.readScalar("brokenBonds");
    if (total > broken) {
      // Bonds broke in this step: every sub-iteration that broke some was reported, and the last report
      // counts the bonds broken in the step so far (pairs: both directions of a bond are one pair here).
      REQUIRE(last.count("subIterations") == 1);
      REQUIRE(last.count("brokenBonds") == 1);
      CHECK(last.at("subIterations") >= 1);
      CHECK(last.at("brokenBonds") > 0);
    }
    broken = total;
  }
  CHECK(broken > preCrack);  // the scene does crack, so the branch above ran
  CHECK(reportsInSteps > 0);
}
