// The FMI 3.0 Co-Simulation state machine through the C ABI: every function of the state table
// called in every state. Legal calls return fmi3OK and log nothing; illegal ones return fmi3Error,
// log exactly one message (logStatusError) and leave the instance in Terminated.
#include <array>
#include <catch2/catch.hpp>
#include <functional>

#include "fmi_abi_support.hpp"
#include "fmi_refusal.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

enum At { Instantiated, ConfigurationMode, InitializationMode, StepMode, Terminated };
constexpr std::array<const char*, 5> kStateNames{"Instantiated", "Configuration Mode", "Initialization Mode",
                                                 "Step Mode", "Terminated"};

// A fresh instance on a 9 x 9 grid brought to the state.
void bringTo(Session& s, At state) {
  REQUIRE(s.configure(9, 9) == fmi3OK);
  switch (state) {
    case Instantiated: break;
    case ConfigurationMode: REQUIRE(s.fmu.fmi3EnterConfigurationMode(s.instance) == fmi3OK); break;
    case InitializationMode:
      REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3True, 1) == fmi3OK);
      break;
    case StepMode: REQUIRE(s.initialize() == fmi3OK); break;
    case Terminated:
      REQUIRE(s.initialize() == fmi3OK);
      REQUIRE(s.fmu.fmi3Terminate(s.instance) == fmi3OK);
      break;
  }
  REQUIRE(s.log.records.empty());
}

// Per state: nullptr where the call is legal, "" where the state forbids it, else the fragment of
// the message a variable-level refusal logs.
using Expectation = std::array<const char*, 5>;
constexpr const char* ok = nullptr;
constexpr const char* state = "";

struct Call {
  const char* function;
  std::function<fmi3Status(Session&)> invoke;
  Expectation expected;
};

fmi3Status getOne(Session& s, fmi3ValueReference vr) {
  double v = 0;
  return s.fmu.fmi3GetFloat64(s.instance, &vr, 1, &v, 1);
}

const std::vector<Call>& calls() {
  static const std::vector<Call> table{
      {"fmi3EnterConfigurationMode", [](Session& s) { return s.fmu.fmi3EnterConfigurationMode(s.instance); },
       {ok, state, state, state, state}},
      {"fmi3ExitConfigurationMode", [](Session& s) { return s.fmu.fmi3ExitConfigurationMode(s.instance); },
       {state, ok, state, state, state}},
      {"fmi3EnterInitializationMode",
       [](Session& s) { return s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3False, 0); },
       {ok, state, state, state, state}},
      {"fmi3ExitInitializationMode", [](Session& s) { return s.fmu.fmi3ExitInitializationMode(s.instance); },
       {state, state, ok, state, state}},
      {"fmi3DoStep", [](Session& s) { return s.step(0, 0.25); }, {state, state, state, ok, state}},
      {"fmi3Terminate", [](Session& s) { return s.fmu.fmi3Terminate(s.instance); }, {state, state, state, ok, state}},
      {"fmi3Reset", [](Session& s) { return s.fmu.fmi3Reset(s.instance); }, {ok, ok, ok, ok, ok}},
      {"fmi3SetDebugLogging",
       [](Session& s) { return s.fmu.fmi3SetDebugLogging(s.instance, fmi3True, 0, nullptr); },
       {ok, ok, ok, ok, ok}},
      {"fmi3GetFMUState",
       [](Session& s) {
         fmi3FMUState st = nullptr;
         const fmi3Status status = s.fmu.fmi3GetFMUState(s.instance, &st);
         return status == fmi3OK ? s.fmu.fmi3FreeFMUState(s.instance, &st) : status;
       },
       {ok, ok, ok, ok, ok}},
      {"fmi3GetFloat64", [](Session& s) { return getOne(s, PERISTEP_VR_LX); }, {ok, state, ok, ok, ok}},
      {"fmi3GetFloat64", [](Session& s) { return getOne(s, PERISTEP_VR_ERROR_L2); },
       {"errorL2 (vr 56) has no value before Initialization Mode", state, ok, ok, ok}},
      {"fmi3SetFloat64", [](Session& s) { return s.setFloat64(PERISTEP_VR_LX, {1.0}); },
       {ok, "Lx (vr 11) cannot be set in Configuration Mode", ok,
        "Lx (vr 11) is a fixed parameter and cannot change in Step Mode", state}},
      {"fmi3SetFloat64", [](Session& s) { return s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.5}); },
       {ok, "loadFactor (vr 30) cannot be set in Configuration Mode", ok, ok, state}},
      {"fmi3SetUInt64",
       [](Session& s) {
         const fmi3ValueReference vr = PERISTEP_VR_NX;
         const fmi3UInt64 nx = 9;
         return s.fmu.fmi3SetUInt64(s.instance, &vr, 1, &nx, 1);
       },
       {"nx (vr 1) is a structural parameter: set it in Configuration Mode", ok,
        "nx (vr 1) is a structural parameter", "nx (vr 1) is a structural parameter", state}},
      {"fmi3EnterStepMode", [](Session& s) { return s.fmu.fmi3EnterStepMode(s.instance); },
       {"no Event Mode", "no Event Mode", "no Event Mode", "no Event Mode", "no Event Mode"}},
      {"fmi3EnterEventMode", [](Session& s) { return s.fmu.fmi3EnterEventMode(s.instance); },
       {"no Event Mode", "no Event Mode", "no Event Mode", "no Event Mode", "no Event Mode"}},
  };
  return table;
}

}  // namespace

TEST_CASE("every function of the state table is legal exactly where the standard allows it", "[abi][states]") {
  for (const Call& call : calls())
    for (int at = Instantiated; at <= Terminated; ++at) {
      INFO(call.function << " in state " << kStateNames[at]);
      Session s;
      bringTo(s, static_cast<At>(at));
      const fmi3Status status = call.invoke(s);
      const char* expected = call.expected[at];
      if (expected == ok) {
        CHECK(status == fmi3OK);
        CHECK(s.log.errors() == 0);
        continue;
      }
      CHECK(status == fmi3Error);
      requireOneError(s, call.function,
                      *expected ? expected : std::string("illegal call in state ") + kStateNames[at]);
      // After fmi3Error the instance is in Terminated (FMI 3.0 Sec. 2.3.1): stepping is illegal there.
      s.log.clear();
      CHECK(s.step(0, 0.25) == fmi3Error);
      requireOneError(s, "fmi3DoStep", "illegal call in state Terminated");
    }
}

TEST_CASE("Terminated allows getters, FMU states and reset, and reset starts over", "[abi][states]") {
  Session s;
  bringTo(s, Terminated);
  CHECK(s.getFloat64(PERISTEP_VR_ERROR_L2).size() == 1);
  CHECK(s.fmu.fmi3Reset(s.instance) == fmi3OK);
  CHECK(s.configure(9, 9) == fmi3OK);
  CHECK(s.initialize() == fmi3OK);
  CHECK(s.step(0, 0.5) == fmi3OK);
  CHECK(s.log.records.empty());
}

TEST_CASE("Get after Set follows the standard", "[abi][states]") {
  Session s;
  REQUIRE(s.configure(9, 9) == fmi3OK);

  SECTION("parameters read back as set, before and during initialization") {
    CHECK(s.setFloat64(PERISTEP_VR_LX, {2.0}) == fmi3OK);
    CHECK(s.getFloat64(PERISTEP_VR_LX) == std::vector<double>{2.0});
    REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3True, 1) == fmi3OK);
    CHECK(s.setFloat64(PERISTEP_VR_LY, {2.0}) == fmi3OK);
    CHECK(s.getFloat64(PERISTEP_VR_LY) == std::vector<double>{2.0});
    const fmi3ValueReference nx = PERISTEP_VR_NX;
    fmi3UInt64 value = 0;
    CHECK(s.fmu.fmi3GetUInt64(s.instance, &nx, 1, &value, 1) == fmi3OK);
    CHECK(value == 9);
    // the calculated coordinates follow the parameters set in Initialization Mode: x spans [-1, 1]
    const auto x = s.getFloat64(PERISTEP_VR_X, 81);
    REQUIRE(x.size() == 81);
    CHECK(x.front() == Approx(-1.0));
    CHECK(x[8] == Approx(1.0));
    CHECK(s.log.records.empty());
  }

  SECTION("outputs in Initialization Mode follow the inputs set there") {
    REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3True, 1) == fmi3OK);
    const auto full = s.getFloat64(PERISTEP_VR_UX, 81);
    REQUIRE(full.size() == 81);
    CHECK(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.5}) == fmi3OK);
    const auto half = s.getFloat64(PERISTEP_VR_UX, 81);
    REQUIRE(half.size() == 81);
    for (std::size_t p = 0; p < 81; ++p) CHECK(half[p] == Approx(0.5 * full[p]).margin(1e-15));
    CHECK(s.getFloat64(PERISTEP_VR_LOAD_FACTOR) == std::vector<double>{0.5});
    CHECK(s.log.records.empty());
  }

  SECTION("in Step Mode values are read after fmi3DoStep, not between a Set and the step") {
    REQUIRE(s.initialize() == fmi3OK);
    CHECK(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.5}) == fmi3OK);
    CHECK(s.getFloat64(PERISTEP_VR_ERROR_L2).empty());
    requireOneError(s, "fmi3GetFloat64", "values were set after the last fmi3DoStep");
  }

  SECTION("in Step Mode the step publishes the outputs of the input set before it") {
    REQUIRE(s.initialize() == fmi3OK);
    const auto full = s.getFloat64(PERISTEP_VR_UY, 81);
    CHECK(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {-2.0}) == fmi3OK);
    REQUIRE(s.step(0, 0.25) == fmi3OK);
    const auto scaled = s.getFloat64(PERISTEP_VR_UY, 81);
    REQUIRE(scaled.size() == 81);
    for (std::size_t p = 0; p < 81; ++p) CHECK(scaled[p] == Approx(-2.0 * full[p]).margin(1e-15));
    CHECK(s.log.records.empty());
  }
}
