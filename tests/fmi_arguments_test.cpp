// Bad arguments through the C ABI: unknown value references, wrong array sizes, NULL pointers, NaN
// and non-physical values, inconsistent parameters, failed instantiation, unsupported functions and
// the logging switches. Every refusal is fmi3Error with exactly one precise message.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>

#include "fmi_abi_support.hpp"
#include "fmi_refusal.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

fmi3Status setUInt64(Session& s, fmi3ValueReference vr, fmi3UInt64 value) {
  return s.fmu.fmi3SetUInt64(s.instance, &vr, 1, &value, 1);
}

// fmi3InstantiateCoSimulation with one argument changed; the messages go to log.
fmi3Instance instantiate(LogRecorder& log, const char* name, const char* token, bool eventModeUsed = false,
                         std::size_t nRequired = 0) {
  const fmi3ValueReference required[] = {PERISTEP_VR_UX};
  return Fmu::get().fmi3InstantiateCoSimulation(name, token, nullptr, fmi3False, fmi3True, eventModeUsed,
                                                fmi3False, required, nRequired, &log, recordMessage, nullptr);
}

}  // namespace

TEST_CASE("non-physical and non-finite values are refused when they are set", "[abi][arguments]") {
  Session s;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  SECTION("poissonRatio 0.5") {
    requireRefused(s, "fmi3SetFloat64", "poissonRatio (vr 14) must lie in (-1, 0.5), got 0.5",
                   [&] { return s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.5}); });
  }
  SECTION("poissonRatio NaN") {
    requireRefused(s, "fmi3SetFloat64", "poissonRatio (vr 14) must be finite, got NaN",
                   [&] { return s.setFloat64(PERISTEP_VR_POISSON_RATIO, {nan}); });
  }
  SECTION("deltaOverH 0.5") {
    requireRefused(s, "fmi3SetFloat64", "deltaOverH (vr 13) must lie in [1, 20], got 0.5",
                   [&] { return s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {0.5}); });
  }
  SECTION("deltaOverH 1e12") {
    requireRefused(s, "fmi3SetFloat64", "deltaOverH (vr 13) must lie in [1, 20], got 1e+12",
                   [&] { return s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {1e12}); });
  }
  SECTION("Lx 0") {
    requireRefused(s, "fmi3SetFloat64", "Lx (vr 11) must lie in (0, inf), got 0",
                   [&] { return s.setFloat64(PERISTEP_VR_LX, {0.0}); });
  }
  SECTION("Lx negative") {
    requireRefused(s, "fmi3SetFloat64", "Lx (vr 11) must lie in (0, inf), got -1",
                   [&] { return s.setFloat64(PERISTEP_VR_LX, {-1.0}); });
  }
  SECTION("Ly infinite") {
    requireRefused(s, "fmi3SetFloat64", "Ly (vr 12) must be finite, got inf",
                   [&] { return s.setFloat64(PERISTEP_VR_LY, {inf}); });
  }
  SECTION("a negative modulus") {
    requireRefused(s, "fmi3SetFloat64", "bulkModulus (vr 74) must lie in (0, inf), got -2.5e+10",
                   [&] { return s.setFloat64(PERISTEP_VR_BULK_MODULUS, {-25e9}); });
  }
  SECTION("a zero fracture energy") {
    requireRefused(s, "fmi3SetFloat64", "glassFractureEnergy (vr 72) must lie in (0, inf), got 0",
                   [&] { return s.setFloat64(PERISTEP_VR_GLASS_FRACTURE_ENERGY, {0.0}); });
  }
  SECTION("modulusContrast 0") {
    requireRefused(s, "fmi3SetFloat64", "modulusContrast (vr 15) must lie in (0, inf)",
                   [&] { return s.setFloat64(PERISTEP_VR_MODULUS_CONTRAST, {0.0}); });
  }
  SECTION("jitter 0.5") {
    requireRefused(s, "fmi3SetFloat64", "jitter (vr 16) must lie in [0, 0.5), got 0.5",
                   [&] { return s.setFloat64(PERISTEP_VR_JITTER, {0.5}); });
  }
  SECTION("xi NaN, naming the element") {
    REQUIRE(s.configure(9, 9, 3) == fmi3OK);
    requireRefused(s, "fmi3SetFloat64", "xi (vr 19)[2] must be finite",
                   [&] { return s.setFloat64(PERISTEP_VR_XI, {0.0, 1.0, nan}); });
  }
  SECTION("loadFactor NaN in Step Mode") {
    REQUIRE(s.configure(9, 9) == fmi3OK);
    REQUIRE(s.initialize() == fmi3OK);
    requireRefused(s, "fmi3SetFloat64", "loadFactor (vr 30) must be finite",
                   [&] { return s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {nan}); });
  }
  SECTION("nx 1") {
    REQUIRE(s.fmu.fmi3EnterConfigurationMode(s.instance) == fmi3OK);
    requireRefused(s, "fmi3SetUInt64", "nx (vr 1) must lie in [2, 65536], got 1",
                   [&] { return setUInt64(s, PERISTEP_VR_NX, 1); });
  }
  SECTION("nModes 0") {
    REQUIRE(s.fmu.fmi3EnterConfigurationMode(s.instance) == fmi3OK);
    requireRefused(s, "fmi3SetUInt64", "nModes (vr 3) must lie in [1, 1024], got 0",
                   [&] { return setUInt64(s, PERISTEP_VR_NMODES, 0); });
  }
  SECTION("an enumeration value that does not exist") {
    requireRefused(s, "fmi3SetInt64",
                   "scene (vr 10) = 99 is not a value of PeriStep.Scene (1 smooth, 2 composite, 3 interfaceCrack, 4 "
                   "glassCeramic, 5 plexiglassCrack",
                   [&] { return s.setInt64(PERISTEP_VR_SCENE, 99); });
  }
  // A refused call stores nothing (and, per the standard, leaves the instance in Terminated).
  CHECK(s.getFloat64(PERISTEP_VR_POISSON_RATIO) == std::vector<double>{0.3});
  CHECK(s.getFloat64(PERISTEP_VR_LX) == std::vector<double>{1.0});
}

TEST_CASE("a rejected Set call changes no value, even the valid ones listed with the bad one", "[abi][arguments]") {
  Session s;
  const fmi3ValueReference vr[] = {PERISTEP_VR_LX, PERISTEP_VR_POISSON_RATIO};
  const double values[] = {2.0, 0.7};
  requireRefused(s, "fmi3SetFloat64", "poissonRatio",
                 [&] { return s.fmu.fmi3SetFloat64(s.instance, vr, 2, values, 2); });
  CHECK(s.getFloat64(PERISTEP_VR_LX) == std::vector<double>{1.0});
}

TEST_CASE("parameters that are valid alone but inconsistent together fail at initialization", "[abi][arguments]") {
  Session s;
  REQUIRE(s.configure(9, 9) == fmi3OK);
  SECTION("non-uniform spacing") {
    REQUIRE(s.setFloat64(PERISTEP_VR_LY, {2.0}) == fmi3OK);
    REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3True, 1) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode", "grid spacing must be uniform",
                   [&] { return s.fmu.fmi3ExitInitializationMode(s.instance); });
  }
  SECTION("too few random coordinates for the composite scene") {
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_COMPOSITE) == fmi3OK);
    REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3True, 1) == fmi3OK);
    requireRefused(s, "fmi3GetFloat64", "scene needs 2 random coordinates but nModes = 1",
                   [&] { return s.getFloat64(PERISTEP_VR_UX, 81).empty() ? fmi3Error : fmi3OK; });
  }
}

TEST_CASE("value references, types, array sizes and pointers are checked", "[abi][arguments]") {
  Session s;
  REQUIRE(s.configure(9, 9) == fmi3OK);
  REQUIRE(s.initialize() == fmi3OK);
  const Fmu& f = s.fmu;
  std::vector<double> buffer(100);
  SECTION("unknown value reference") {
    const fmi3ValueReference vr[] = {PERISTEP_VR_LX, 999};
    requireRefused(s, "fmi3GetFloat64", "unknown value reference 999",
                   [&] { return f.fmi3GetFloat64(s.instance, vr, 2, buffer.data(), 2); });
  }
  SECTION("nValues smaller than the listed arrays") {
    const fmi3ValueReference vr[] = {PERISTEP_VR_ERROR_L2, PERISTEP_VR_UX};
    requireRefused(s, "fmi3GetFloat64", "nValues = 10 but the listed variables have 82 elements",
                   [&] { return f.fmi3GetFloat64(s.instance, vr, 2, buffer.data(), 10); });
  }
  SECTION("nValues larger than a scalar") {
    requireRefused(s, "fmi3SetFloat64", "nValues = 2 but the listed variables have 1 elements",
                   [&] { return s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {1.0, 2.0}); });
  }
  SECTION("NULL value references") {
    requireRefused(s, "fmi3GetFloat64", "valueReferences is NULL",
                   [&] { return f.fmi3GetFloat64(s.instance, nullptr, 1, buffer.data(), 1); });
  }
  SECTION("NULL values") {
    const fmi3ValueReference vr = PERISTEP_VR_LOAD_FACTOR;
    requireRefused(s, "fmi3SetFloat64", "values is NULL",
                   [&] { return f.fmi3SetFloat64(s.instance, &vr, 1, nullptr, 1); });
  }
  SECTION("a Float64 variable read as UInt64") {
    const fmi3ValueReference vr = PERISTEP_VR_LX;
    fmi3UInt64 v = 0;
    requireRefused(s, "fmi3GetUInt64", "Lx (vr 11) is a Float64 variable, not UInt64",
                   [&] { return f.fmi3GetUInt64(s.instance, &vr, 1, &v, 1); });
  }
  SECTION("an enumeration read as Float64") {
    requireRefused(s, "fmi3GetFloat64", "fmi3GetInt64/fmi3SetInt64",
                   [&] { return s.getFloat64(PERISTEP_VR_SCENE).empty() ? fmi3Error : fmi3OK; });
  }
  SECTION("a type no variable has") {
    const fmi3ValueReference vr = PERISTEP_VR_LOAD_FACTOR;
    const fmi3Boolean v = fmi3True;
    requireRefused(s, "fmi3SetBoolean", "loadFactor (vr 30) is a Float64 variable, not Boolean",
                   [&] { return f.fmi3SetBoolean(s.instance, &vr, 1, &v, 1); });
  }
  SECTION("an output cannot be set") {
    requireRefused(s, "fmi3SetFloat64", "ux (vr 40) is an output and cannot be set",
                   [&] { return s.setFloat64(PERISTEP_VR_UX, std::vector<double>(81, 0.0)); });
  }
  SECTION("a calculated parameter cannot be set") {
    const fmi3ValueReference vr = PERISTEP_VR_XI_DISTRIBUTION;
    const fmi3Int32 v = 1;
    requireRefused(s, "fmi3SetInt32", "xiDistribution (vr 20) is a calculatedParameter and cannot be set",
                   [&] { return f.fmi3SetInt32(s.instance, &vr, 1, &v, 1); });
  }
  SECTION("time cannot be set") {
    requireRefused(s, "fmi3SetFloat64", "time (vr 0) is the independent variable",
                   [&] { return s.setFloat64(PERISTEP_VR_TIME, {0.5}); });
  }
  SECTION("NULL output arguments of fmi3DoStep") {
    fmi3Boolean flag;
    fmi3Float64 last;
    requireRefused(s, "fmi3DoStep", "earlyReturn is NULL", [&] {
      return f.fmi3DoStep(s.instance, 0, 0.25, fmi3False, &flag, &flag, nullptr, &last);
    });
  }
  SECTION("a communication point that is not the FMU's time") {
    requireRefused(s, "fmi3DoStep", "currentCommunicationPoint = 0.5 but the FMU is at time 0",
                   [&] { return s.step(0.5, 0.25); });
  }
  SECTION("a step size that is not positive") {
    requireRefused(s, "fmi3DoStep", "communicationStepSize must be positive and finite, got 0",
                   [&] { return s.step(0, 0); });
  }
  SECTION("a step past stopTime") {
    requireRefused(s, "fmi3DoStep", "passes stopTime = 1", [&] { return s.step(0, 1.5); });
  }
  SECTION("an unknown log category") {
    const fmi3String categories[] = {"logEvents", "logEverything"};
    requireRefused(s, "fmi3SetDebugLogging", "unknown log category 'logEverything'",
                   [&] { return f.fmi3SetDebugLogging(s.instance, fmi3True, 2, categories); });
  }
}

TEST_CASE("a NULL instance is refused without a crash", "[abi][arguments]") {
  const Fmu& f = Fmu::get();
  const fmi3ValueReference vr = PERISTEP_VR_LX;
  double v = 0;
  CHECK(f.fmi3GetFloat64(nullptr, &vr, 1, &v, 1) == fmi3Error);
  CHECK(f.fmi3DoStep(nullptr, 0, 1, fmi3False, nullptr, nullptr, nullptr, nullptr) == fmi3Error);
  CHECK(f.fmi3Reset(nullptr) == fmi3Error);
  f.fmi3FreeInstance(nullptr);  // no effect
}

TEST_CASE("instantiation checks its arguments and says why it fails", "[abi][arguments]") {
  LogRecorder log;
  SECTION("wrong instantiation token") {
    CHECK(instantiate(log, "a", "{00000000-0000-0000-0000-000000000000}") == nullptr);
    REQUIRE(log.records.size() == 1);
    CHECK_THAT(log.records[0].message, StartsWith("fmi3InstantiateCoSimulation: instantiationToken"));
    CHECK(log.records[0].status == fmi3Error);
  }
  SECTION("blank instance name") {
    CHECK(instantiate(log, "  ", PERISTEP_INSTANTIATION_TOKEN) == nullptr);
    REQUIRE(log.records.size() == 1);
    CHECK_THAT(log.records[0].message, Contains("instanceName must be a non-empty string"));
  }
  SECTION("NULL token") {
    CHECK(instantiate(log, "a", nullptr) == nullptr);
    REQUIRE(log.records.size() == 1);
    CHECK_THAT(log.records[0].message, Contains("instantiationToken is NULL"));
  }
  SECTION("Event Mode requested") {
    CHECK(instantiate(log, "a", PERISTEP_INSTANTIATION_TOKEN, true) == nullptr);
    REQUIRE(log.records.size() == 1);
    CHECK_THAT(log.records[0].message, Contains("hasEventMode = false"));
  }
  SECTION("intermediate variables requested") {
    CHECK(instantiate(log, "a", PERISTEP_INSTANTIATION_TOKEN, false, 1) == nullptr);
    REQUIRE(log.records.size() == 1);
    CHECK_THAT(log.records[0].message, Contains("no intermediate update"));
  }
  SECTION("Model Exchange and Scheduled Execution") {
    const Fmu& f = Fmu::get();
    CHECK(f.fmi3InstantiateModelExchange("a", PERISTEP_INSTANTIATION_TOKEN, nullptr, fmi3False, fmi3True, &log,
                                         recordMessage) == nullptr);
    CHECK(f.fmi3InstantiateScheduledExecution("a", PERISTEP_INSTANTIATION_TOKEN, nullptr, fmi3False, fmi3True, &log,
                                              recordMessage, nullptr, nullptr, nullptr) == nullptr);
    REQUIRE(log.records.size() == 2);
    CHECK_THAT(log.records[0].message, Contains("Co-Simulation FMU"));
    CHECK_THAT(log.records[1].message, Contains("Co-Simulation FMU"));
  }
}

TEST_CASE("unsupported functions log why and return fmi3Error", "[abi][arguments]") {
  Session s;
  REQUIRE(s.configure(9, 9) == fmi3OK);
  REQUIRE(s.initialize() == fmi3OK);
  const Fmu& f = s.fmu;
  fmi3Instance i = s.instance;
  const fmi3ValueReference vr = PERISTEP_VR_UX;
  double d = 0;
  fmi3UInt64 u = 0;
  fmi3Boolean b = fmi3False;
  fmi3Clock clock = fmi3ClockInactive;
  fmi3IntervalQualifier q;
  std::size_t n = 0;
  const fmi3Int32 order = 1;
  const std::vector<std::pair<const char*, std::function<fmi3Status()>>> unsupported{
      {"fmi3GetDirectionalDerivative",
       [&] { return f.fmi3GetDirectionalDerivative(i, &vr, 1, &vr, 1, &d, 1, &d, 1); }},
      {"fmi3GetAdjointDerivative", [&] { return f.fmi3GetAdjointDerivative(i, &vr, 1, &vr, 1, &d, 1, &d, 1); }},
      {"fmi3GetOutputDerivatives", [&] { return f.fmi3GetOutputDerivatives(i, &vr, 1, &order, &d, 1); }},
      {"fmi3GetNumberOfVariableDependencies", [&] { return f.fmi3GetNumberOfVariableDependencies(i, vr, &n); }},
      {"fmi3GetVariableDependencies",
       [&] { return f.fmi3GetVariableDependencies(i, vr, nullptr, nullptr, nullptr, nullptr, 0); }},
      {"fmi3GetClock", [&] { return f.fmi3GetClock(i, &vr, 1, &clock); }},
      {"fmi3SetClock", [&] { return f.fmi3SetClock(i, &vr, 1, &clock); }},
      {"fmi3GetIntervalDecimal", [&] { return f.fmi3GetIntervalDecimal(i, &vr, 1, &d, &q); }},
      {"fmi3GetIntervalFraction", [&] { return f.fmi3GetIntervalFraction(i, &vr, 1, &u, &u, &q); }},
      {"fmi3GetShiftDecimal", [&] { return f.fmi3GetShiftDecimal(i, &vr, 1, &d); }},
      {"fmi3GetShiftFraction", [&] { return f.fmi3GetShiftFraction(i, &vr, 1, &u, &u); }},
      {"fmi3SetIntervalDecimal", [&] { return f.fmi3SetIntervalDecimal(i, &vr, 1, &d); }},
      {"fmi3SetIntervalFraction", [&] { return f.fmi3SetIntervalFraction(i, &vr, 1, &u, &u); }},
      {"fmi3SetShiftDecimal", [&] { return f.fmi3SetShiftDecimal(i, &vr, 1, &d); }},
      {"fmi3SetShiftFraction", [&] { return f.fmi3SetShiftFraction(i, &vr, 1, &u, &u); }},
      {"fmi3EvaluateDiscreteStates", [&] { return f.fmi3EvaluateDiscreteStates(i); }},
      {"fmi3UpdateDiscreteStates", [&] { return f.fmi3UpdateDiscreteStates(i, &b, &b, &b, &b, &b, &d); }},
      {"fmi3EnterContinuousTimeMode", [&] { return f.fmi3EnterContinuousTimeMode(i); }},
      {"fmi3CompletedIntegratorStep", [&] { return f.fmi3CompletedIntegratorStep(i, fmi3False, &b, &b); }},
      {"fmi3SetTime", [&] { return f.fmi3SetTime(i, 0.5); }},
      {"fmi3SetContinuousStates", [&] { return f.fmi3SetContinuousStates(i, &d, 1); }},
      {"fmi3GetContinuousStateDerivatives", [&] { return f.fmi3GetContinuousStateDerivatives(i, &d, 1); }},
      {"fmi3GetEventIndicators", [&] { return f.fmi3GetEventIndicators(i, &d, 1); }},
      {"fmi3GetContinuousStates", [&] { return f.fmi3GetContinuousStates(i, &d, 1); }},
      {"fmi3GetNominalsOfContinuousStates", [&] { return f.fmi3GetNominalsOfContinuousStates(i, &d, 1); }},
      {"fmi3GetNumberOfEventIndicators", [&] { return f.fmi3GetNumberOfEventIndicators(i, &n); }},
      {"fmi3GetNumberOfContinuousStates", [&] { return f.fmi3GetNumberOfContinuousStates(i, &n); }},
      {"fmi3ActivateModelPartition", [&] { return f.fmi3ActivateModelPartition(i, vr, 0.5); }},
  };
  for (const auto& [name, call] : unsupported) {
    INFO(name);
    REQUIRE(f.fmi3Reset(i) == fmi3OK);  // each refusal terminates the instance
    requireRefused(s, name, "", call);
    CHECK((s.log.records.front().message.find("not offered") != std::string::npos ||
           s.log.records.front().message.find("PeriStep") != std::string::npos));
  }
}

TEST_CASE("logging follows loggingOn and fmi3SetDebugLogging", "[abi][logging]") {
  SECTION("loggingOn = false still reports every refusal, and nothing else") {
    Session s(false);
    REQUIRE(s.configure(9, 9) == fmi3OK);
    REQUIRE(s.initialize() == fmi3OK);
    REQUIRE(s.step(0, 0.25) == fmi3OK);
    CHECK(s.log.records.empty());
    CHECK(s.step(0, 1) == fmi3Error);
    REQUIRE(s.log.records.size() == 1);
    CHECK(s.log.records[0].status == fmi3Error);
    CHECK(s.log.records[0].category == "logStatusError");
    CHECK_THAT(s.log.records[0].message, StartsWith("fmi3DoStep: "));
  }
  SECTION("logEvents is off by default and reports steps once switched on") {
    Session s;
    REQUIRE(s.configure(9, 9) == fmi3OK);
    REQUIRE(s.initialize() == fmi3OK);
    REQUIRE(s.step(0, 0.25) == fmi3OK);
    CHECK(s.log.records.empty());
    const fmi3String events[] = {"logEvents"};
    REQUIRE(s.fmu.fmi3SetDebugLogging(s.instance, fmi3True, 1, events) == fmi3OK);
    REQUIRE(s.step(0.25, 0.25) == fmi3OK);
    REQUIRE(s.log.records.size() == 1);
    CHECK(s.log.records[0].status == fmi3OK);
    CHECK(s.log.records[0].category == "logEvents");
    CHECK_THAT(s.log.records[0].message, StartsWith("step to t = 0.5"));
  }
  SECTION("switching every category off does not silence a refusal") {
    Session s;
    REQUIRE(s.fmu.fmi3SetDebugLogging(s.instance, fmi3False, 0, nullptr) == fmi3OK);
    CHECK(s.step(0, 1) == fmi3Error);
    REQUIRE(s.log.records.size() == 1);
    CHECK(s.log.records[0].category == "logStatusError");
  }
}
