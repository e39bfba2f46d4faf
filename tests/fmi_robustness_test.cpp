// Legal input that would run for hours or exhaust memory comes back at once through the C ABI with
// fmi3Error and one message that gives the estimate, the limit and what to change; long
// initializations and steps report progress in the log category logProgress, which is off by default
// and does not change results.
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdint>
#include <regex>

#include "fmi_abi_support.hpp"

using Catch::Matchers::Contains;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

fmi3Status setUInt64(Session& s, fmi3ValueReference vr, std::uint64_t value) {
  return s.fmu.fmi3SetUInt64(s.instance, &vr, 1, &value, 1);
}

// Initialization must fail at once with one message holding every fragment.
void expectRefusedSetUp(Session& s, const std::vector<std::string>& fragments) {
  const auto start = std::chrono::steady_clock::now();
  CHECK(s.initialize() == fmi3Error);
  CHECK(secondsSince(start) < 5);
  REQUIRE(s.log.records.size() == 1);
  CHECK(s.log.records[0].status == fmi3Error);
  for (const auto& f : fragments) CHECK_THAT(s.log.records[0].message, Contains(f));
}

// The Plexiglass square at its coarsest (25 x 25 nodes, eps = 8 mm), the scene's step of 0.004 us.
void plexiglass(Session& s) {
  REQUIRE(s.configure(25, 25) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_PLEXIGLASS_CRACK) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {0.096}) == fmi3OK);  // h = 4 mm: the cells span 0.1 m
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {0.096}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {2.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
}

std::vector<std::string> progressMessages(const LogRecorder& log) {
  std::vector<std::string> m;
  for (const auto& r : log.records)
    if (r.category == "logProgress") m.push_back(r.message);
  return m;
}

void enableProgress(Session& s) {
  const fmi3String category = "logProgress";
  REQUIRE(s.fmu.fmi3SetDebugLogging(s.instance, fmi3True, 1, &category) == fmi3OK);
}

}  // namespace

TEST_CASE("set-ups estimated beyond the limits are refused in initialization with the estimate",
          "[fmi][limits]") {
  Session s;
  SECTION("glass-ceramic at the start values (a 1 m plate of 12 um crystals)") {
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_GLASS_CERAMIC) == fmi3OK);
    expectRefusedSetUp(s, {"fmi3ExitInitializationMode: the scene set-up would take about", "crystals",
                           "setUpTimeLimit = 60 s", "a smaller plate"});
  }
  SECTION("a PCA field of 1e9 realizations") {
    REQUIRE(s.configure(13, 13) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_GLASS_CERAMIC) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LX, {384e-6}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LY, {384e-6}) == fmi3OK);
    REQUIRE(setUInt64(s, PERISTEP_VR_PCA_REALIZATIONS, 1000000000) == fmi3OK);
    expectRefusedSetUp(s, {"the PCA of 1e+09 realizations", "setUpTimeLimit", "fewer pcaRealizations"});
  }
  SECTION("deltaOverH = 20 on the default grid: a dense factorization") {
    REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {20.0}) == fmi3OK);
    expectRefusedSetUp(s, {"the factorization of about 7.5e+03 unknowns", "setUpTimeLimit", "smaller deltaOverH"});
  }
  SECTION("the same within the time limit but beyond a memory budget of 100 MB") {
    REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {20.0}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_SET_UP_TIME_LIMIT, {0.0}) == fmi3OK);
    REQUIRE(setUInt64(s, PERISTEP_VR_MEMORY_BUDGET, 100000000) == fmi3OK);
    expectRefusedSetUp(s, {"would need about", "bytes of memory", "memoryBudget = 1e+08 bytes", "raise memoryBudget"});
  }
  SECTION("a 2000 x 2000 grid (hundreds of GB) under the automatic budget") {
    REQUIRE(s.configure(2000, 2000) == fmi3OK);
    expectRefusedSetUp(s, {"bytes of memory", "memoryBudget"});
  }
}

TEST_CASE("a dynamic step beyond maxInternalSteps is refused up front and changes nothing", "[fmi][limits]") {
  Session s;
  plexiglass(s);
  SECTION("internalTimeStep = 1e-300") {
    REQUIRE(s.setFloat64(PERISTEP_VR_INTERNAL_TIME_STEP, {1e-300}) == fmi3OK);
    REQUIRE(s.initialize(0, 10) == fmi3OK);
    const auto start = std::chrono::steady_clock::now();
    CHECK(s.step(0, 0.25) == fmi3Error);
    CHECK(secondsSince(start) < 1);
    REQUIRE(s.log.records.size() == 1);
    CHECK_THAT(s.log.records[0].message,
               Contains("fmi3DoStep: internalTimeStep 1e-300 s would need 2.5e+299 internal steps in this "
                        "communication step of 0.25 s; the limit is maxInternalSteps = 1000000; use a smaller "
                        "communication step or a larger internal step"));
  }
  SECTION("the scene's own step (0.004 us) and a 0.25 s communication step") {
    REQUIRE(s.initialize(0, 10) == fmi3OK);
    fmi3FMUState before = nullptr;
    REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &before) == fmi3OK);
    CHECK(s.step(0, 0.25) == fmi3Error);
    REQUIRE(s.log.records.size() == 1);
    CHECK_THAT(s.log.records[0].message, Contains("would need 6.25e+07 internal steps"));
    // The refusal happened before any work: the state restores and a short step runs.
    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, before) == fmi3OK);
    CHECK(s.step(0, 2e-6) == fmi3OK);
    REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &before) == fmi3OK);
  }
  SECTION("an adaptive integrator stops at the limit") {
    REQUIRE(s.setInt64(PERISTEP_VR_TIME_INTEGRATOR, PERISTEP_INTEGRATOR_ARKODE_ERK) == fmi3OK);
    REQUIRE(setUInt64(s, PERISTEP_VR_MAX_INTERNAL_STEPS, 10) == fmi3OK);
    REQUIRE(s.initialize(0, 10) == fmi3OK);
    CHECK(s.step(0, 2e-6) == fmi3Error);
    REQUIRE(s.log.records.size() == 1);
    INFO(s.log.records[0].message);
    CHECK_THAT(s.log.records[0].message, Contains("fmi3DoStep"));
  }
  SECTION("a raised limit lets the step run") {
    REQUIRE(setUInt64(s, PERISTEP_VR_MAX_INTERNAL_STEPS, 0) == fmi3OK);  // 0: no limit
    REQUIRE(s.initialize(0, 10) == fmi3OK);
    CHECK(s.step(0, 2e-6) == fmi3OK);
  }
}

TEST_CASE("progress of long set-ups and steps in logProgress, off by default, results unchanged",
          "[fmi][progress]") {
  const std::regex format(R"(progress: (setUp|pcaRealizations|internalSteps) (\d+)/(\d+))");

  SECTION("a dynamic step of 10,000 internal steps") {
    std::vector<double> withProgress, without;
    for (const bool on : {true, false}) {
      Session s;
      plexiglass(s);
      if (on) enableProgress(s);
      REQUIRE(s.initialize(0, 10) == fmi3OK);
      REQUIRE(s.step(0, 4e-5) == fmi3OK);
      const auto messages = progressMessages(s.log);
      (on ? withProgress : without) = s.getFloat64(PERISTEP_VR_UY, 25 * 25);
      if (!on) {
        CHECK(messages.empty());  // loggingOn alone does not switch progress on
        continue;
      }
      REQUIRE(messages.size() >= 4);
      std::uint64_t last = 0;
      std::size_t steps = 0;
      for (const auto& m : messages) {
        std::smatch match;
        REQUIRE(std::regex_match(m, match, format));
        if (match[1] != "internalSteps") continue;
        ++steps;
        CHECK(match[3] == "10000");
        const auto done = std::stoull(match[2]);
        CHECK(done > last);
        last = done;
      }
      CHECK(steps >= 5);
      CHECK(last == 10000);
      CHECK(messages.front() == "progress: setUp 0/1");
    }
    CHECK(withProgress == without);
  }

  SECTION("a glass-ceramic PCA field") {
    Session s;
    enableProgress(s);
    REQUIRE(s.configure(13, 13) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_GLASS_CERAMIC) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LX, {384e-6}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LY, {384e-6}) == fmi3OK);
    REQUIRE(setUInt64(s, PERISTEP_VR_PCA_REALIZATIONS, 37) == fmi3OK);  // no other test uses 37: not cached
    REQUIRE(s.initialize() == fmi3OK);
    const auto messages = progressMessages(s.log);
    std::size_t pca = 0;
    for (const auto& m : messages) {
      std::smatch match;
      REQUIRE(std::regex_match(m, match, format));
      if (match[1] == "pcaRealizations") {
        ++pca;
        CHECK(match[3] == std::to_string(37 * 8));  // n realizations in each of q + 2 = 8 passes
      }
    }
    CHECK(pca >= 2);
    REQUIRE(messages.size() >= 2);
    CHECK(messages.back() == "progress: setUp 1/1");
  }
}
