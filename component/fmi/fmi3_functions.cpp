// The exported FMI 3.0 functions. Each one checks its instance pointer and the state machine, runs
// its work inside try/catch, and turns any exception into fmi3Error with exactly one message in
// category logStatusError (no exception crosses the C ABI). Functions of interface types and
// features PeriStep does not offer log why and return fmi3Error.
#include <cctype>
#include <cstring>
#include <new>
#include <string>

#include "core/errors.hpp"
#include "fmi/instance.hpp"
#include "fmi/model_identity.hpp"
#include "fmi3Functions.h"

using peristep::InvalidInput;
using peristep::require;
using namespace peristep::fmi;

namespace {

Instance& self(fmi3Instance instance) { return *static_cast<Instance*>(instance); }

// A NULL instance has no logger to report to: the status alone says it.
template <class Body>
fmi3Status guarded(fmi3Instance instance, const char* function, unsigned allowedStates, Body&& body) noexcept {
  if (!instance) return fmi3Error;
  Instance& s = self(instance);
  try {
    requireState(s.state(), allowedStates);
    body(s);
    return fmi3OK;
  } catch (const std::bad_alloc&) {
    s.fail(function, "out of memory");
  } catch (const std::exception& e) {
    s.fail(function, e.what());
  } catch (...) {
    s.fail(function, "unexpected internal error");
  }
  return fmi3Error;
}

fmi3Status unsupported(fmi3Instance instance, const char* function, const char* why) noexcept {
  return guarded(instance, function, kAnyState, [why](Instance&) { throw InvalidInput(why); });
}

constexpr const char* kModelExchange = "Model Exchange is not offered: PeriStep is a Co-Simulation FMU";
constexpr const char* kNoClocks = "PeriStep has no clocks";
constexpr const char* kNoEventMode = "PeriStep has no Event Mode (hasEventMode = false)";

// A C array argument: NULL is only acceptable when it has no elements.
template <class T>
std::span<T> array(T* p, size_t n, const char* name) {
  require(p != nullptr || n == 0, std::string(name) + " is NULL");
  return {p, n};
}

void requireNonNull(const void* p, const char* name) { require(p != nullptr, std::string(name) + " is NULL"); }

template <class T>
fmi3Status getValues(fmi3Instance instance, const char* function, const fmi3ValueReference vrs[], size_t nvr,
                     T values[], size_t nValues) noexcept {
  return guarded(instance, function, allowed::Get, [&](Instance& s) {
    s.get<T>(array(vrs, nvr, "valueReferences"), array(values, nValues, "values"));
  });
}

template <class T>
fmi3Status setValues(fmi3Instance instance, const char* function, const fmi3ValueReference vrs[], size_t nvr,
                     const T values[], size_t nValues) noexcept {
  return guarded(instance, function, allowed::Set, [&](Instance& s) {
    s.set<T>(array(vrs, nvr, "valueReferences"), array(values, nValues, "values"));
  });
}

// Getters and setters of types that no PeriStep variable has (valueSizes: Binary only).
fmi3Status refuseValues(fmi3Instance instance, const char* function, unsigned states, const char* type,
                        const fmi3ValueReference vrs[], size_t nvr, const void* values, size_t nValues,
                        const size_t* valueSizes = nullptr) noexcept {
  return guarded(instance, function, states, [&](Instance& s) {
    const auto list = array(vrs, nvr, "valueReferences");
    require(values != nullptr || nValues == 0, "values is NULL");
    if (std::string_view(type) == "Binary") require(valueSizes != nullptr || nValues == 0, "valueSizes is NULL");
    s.refuseType(type, list, nValues);
  });
}

// Instantiation failures have no instance yet: report through the importer's callback directly.
fmi3Instance refuseInstance(fmi3LogMessageCallback logMessage, fmi3InstanceEnvironment environment,
                            const char* function, const std::string& why) noexcept {
  if (logMessage) {
    try {
      const std::string message = std::string(function) + ": " + why;
      logMessage(environment, fmi3Error, kLogCategories[static_cast<size_t>(LogCategory::StatusError)].name.data(),
                 message.c_str());
    } catch (...) {
      // no memory for the message
    }
  }
  return nullptr;
}

bool blank(const char* s) {
  for (; *s; ++s)
    if (!std::isspace(static_cast<unsigned char>(*s))) return false;
  return true;
}

}  // namespace

extern "C" {

/* ---- Common functions ---- */

const char* fmi3GetVersion(void) { return fmi3Version; }

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
  return guarded(instance, "fmi3SetDebugLogging", allowed::SetDebugLogging, [&](Instance& s) {
    // With nCategories == 0 the array is undefined (FMI 3.0 Sec. 2.3.1) and is not read.
    s.logger().setDebugLogging(loggingOn, array(categories, nCategories, "categories"));
  });
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
  return refuseInstance(logMessage, instanceEnvironment, "fmi3InstantiateModelExchange", kModelExchange);
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath,
                                         fmi3Boolean /*visible: there is nothing to show*/, fmi3Boolean loggingOn,
                                         fmi3Boolean eventModeUsed, fmi3Boolean /*earlyReturnAllowed: never used*/,
                                         const fmi3ValueReference /*requiredIntermediateVariables*/[],
                                         size_t nRequiredIntermediateVariables,
                                         fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback /*intermediateUpdate: not offered*/) {
  constexpr const char* function = "fmi3InstantiateCoSimulation";
  const auto refuse = [&](const std::string& why) {
    return refuseInstance(logMessage, instanceEnvironment, function, why);
  };
  try {
    if (!instanceName || blank(instanceName)) return refuse("instanceName must be a non-empty string");
    if (!instantiationToken) return refuse("instantiationToken is NULL");
    if (std::string_view(instantiationToken) != kInstantiationToken)
      return refuse(std::string("instantiationToken ") + instantiationToken + " does not match this PeriStep.so (" +
                    std::string(kInstantiationToken) + "): modelDescription.xml comes from another build");
    if (eventModeUsed) return refuse("eventModeUsed = true, but PeriStep has no Event Mode (hasEventMode = false)");
    if (nRequiredIntermediateVariables > 0)
      return refuse("requiredIntermediateVariables: PeriStep offers no intermediate update");
    // The resources hold the MD frames of scene learnedFracture; the other scenes need none.
    auto* instance = new Instance(Logger(logMessage, instanceEnvironment, loggingOn), resourcePath ? resourcePath : "");
    instance->logger().event(std::string("instantiated ") + instanceName);
    return instance;
  } catch (...) {
    return refuse("out of memory");
  }
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback,
                                               fmi3LockPreemptionCallback, fmi3UnlockPreemptionCallback) {
  return refuseInstance(logMessage, instanceEnvironment, "fmi3InstantiateScheduledExecution",
                        "Scheduled Execution is not offered: PeriStep is a Co-Simulation FMU");
}

void fmi3FreeInstance(fmi3Instance instance) { delete static_cast<Instance*>(instance); }  // NULL: no effect

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean /*toleranceDefined*/,
                                       fmi3Float64 /*tolerance: each step is a direct solve*/, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
  return guarded(instance, "fmi3EnterInitializationMode", allowed::EnterInitializationMode,
                 [&](Instance& s) { s.enterInitializationMode(startTime, stopTimeDefined, stopTime); });
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
  return guarded(instance, "fmi3ExitInitializationMode", allowed::ExitInitializationMode,
                 [](Instance& s) { s.exitInitializationMode(); });
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) {
  return unsupported(instance, "fmi3EnterEventMode", kNoEventMode);
}

fmi3Status fmi3Terminate(fmi3Instance instance) {
  return guarded(instance, "fmi3Terminate", allowed::Terminate, [](Instance& s) { s.terminate(); });
}

fmi3Status fmi3Reset(fmi3Instance instance) {
  return guarded(instance, "fmi3Reset", allowed::Reset, [](Instance& s) { s.reset(); });
}

/* Getters */

fmi3Status fmi3GetFloat32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float32 values[],
                          size_t nValues) {
  return refuseValues(instance, "fmi3GetFloat32", allowed::Get, "Float32", vr, nvr, values, nValues);
}
fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t nValues) {
  return getValues(instance, "fmi3GetFloat64", vr, nvr, values, nValues);
}
fmi3Status fmi3GetInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int8 values[],
                       size_t nValues) {
  return refuseValues(instance, "fmi3GetInt8", allowed::Get, "Int8", vr, nvr, values, nValues);
}
fmi3Status fmi3GetUInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt8 values[],
                        size_t nValues) {
  return refuseValues(instance, "fmi3GetUInt8", allowed::Get, "UInt8", vr, nvr, values, nValues);
}
fmi3Status fmi3GetInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int16 values[],
                        size_t nValues) {
  return refuseValues(instance, "fmi3GetInt16", allowed::Get, "Int16", vr, nvr, values, nValues);
}
fmi3Status fmi3GetUInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt16 values[],
                         size_t nValues) {
  return refuseValues(instance, "fmi3GetUInt16", allowed::Get, "UInt16", vr, nvr, values, nValues);
}
fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int32 values[],
                        size_t nValues) {
  return getValues(instance, "fmi3GetInt32", vr, nvr, values, nValues);
}
fmi3Status fmi3GetUInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt32 values[],
                         size_t nValues) {
  return refuseValues(instance, "fmi3GetUInt32", allowed::Get, "UInt32", vr, nvr, values, nValues);
}
fmi3Status fmi3GetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int64 values[],
                        size_t nValues) {
  return getValues(instance, "fmi3GetInt64", vr, nvr, values, nValues);
}
fmi3Status fmi3GetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt64 values[],
                         size_t nValues) {
  return getValues(instance, "fmi3GetUInt64", vr, nvr, values, nValues);
}
fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Boolean values[],
                          size_t nValues) {
  return refuseValues(instance, "fmi3GetBoolean", allowed::Get, "Boolean", vr, nvr, values, nValues);
}
fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3String values[],
                         size_t nValues) {
  return refuseValues(instance, "fmi3GetString", allowed::Get, "String", vr, nvr, values, nValues);
}
fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, size_t valueSizes[],
                         fmi3Binary values[], size_t nValues) {
  return refuseValues(instance, "fmi3GetBinary", allowed::Get, "Binary", vr, nvr, values, nValues, valueSizes);
}
fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3Clock[]) {
  return unsupported(instance, "fmi3GetClock", kNoClocks);
}

/* Setters */

fmi3Status fmi3SetFloat32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Float32 values[],
                          size_t nValues) {
  return refuseValues(instance, "fmi3SetFloat32", allowed::Set, "Float32", vr, nvr, values, nValues);
}
fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 values[],
                          size_t nValues) {
  return setValues(instance, "fmi3SetFloat64", vr, nvr, values, nValues);
}
fmi3Status fmi3SetInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int8 values[],
                       size_t nValues) {
  return refuseValues(instance, "fmi3SetInt8", allowed::Set, "Int8", vr, nvr, values, nValues);
}
fmi3Status fmi3SetUInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt8 values[],
                        size_t nValues) {
  return refuseValues(instance, "fmi3SetUInt8", allowed::Set, "UInt8", vr, nvr, values, nValues);
}
fmi3Status fmi3SetInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int16 values[],
                        size_t nValues) {
  return refuseValues(instance, "fmi3SetInt16", allowed::Set, "Int16", vr, nvr, values, nValues);
}
fmi3Status fmi3SetUInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt16 values[],
                         size_t nValues) {
  return refuseValues(instance, "fmi3SetUInt16", allowed::Set, "UInt16", vr, nvr, values, nValues);
}
fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int32 values[],
                        size_t nValues) {
  return setValues(instance, "fmi3SetInt32", vr, nvr, values, nValues);
}
fmi3Status fmi3SetUInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt32 values[],
                         size_t nValues) {
  return refuseValues(instance, "fmi3SetUInt32", allowed::Set, "UInt32", vr, nvr, values, nValues);
}
fmi3Status fmi3SetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int64 values[],
                        size_t nValues) {
  return setValues(instance, "fmi3SetInt64", vr, nvr, values, nValues);
}
fmi3Status fmi3SetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt64 values[],
                         size_t nValues) {
  return setValues(instance, "fmi3SetUInt64", vr, nvr, values, nValues);
}
fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Boolean values[],
                          size_t nValues) {
  return refuseValues(instance, "fmi3SetBoolean", allowed::Set, "Boolean", vr, nvr, values, nValues);
}
fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3String values[],
                         size_t nValues) {
  return refuseValues(instance, "fmi3SetString", allowed::Set, "String", vr, nvr, values, nValues);
}
fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const size_t valueSizes[],
                         const fmi3Binary values[], size_t nValues) {
  return refuseValues(instance, "fmi3SetBinary", allowed::Set, "Binary", vr, nvr, values, nValues, valueSizes);
}
fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Clock[]) {
  return unsupported(instance, "fmi3SetClock", kNoClocks);
}

/* Variable dependencies: <ModelStructure> in modelDescription.xml holds them. */

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference, size_t*) {
  return unsupported(instance, "fmi3GetNumberOfVariableDependencies",
                     "not offered (providesPerElementDependencies = false); see <ModelStructure>");
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference, size_t[], fmi3ValueReference[],
                                       size_t[], fmi3DependencyKind[], size_t) {
  return unsupported(instance, "fmi3GetVariableDependencies",
                     "not offered (providesPerElementDependencies = false); see <ModelStructure>");
}

/* FMU state */

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
  return guarded(instance, "fmi3GetFMUState", allowed::FMUState, [&](Instance& s) {
    requireNonNull(FMUState, "FMUState");
    *FMUState = s.saveState(static_cast<Snapshot*>(*FMUState));
  });
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
  return guarded(instance, "fmi3SetFMUState", allowed::FMUState,
                 [&](Instance& s) { s.restoreState(static_cast<const Snapshot*>(FMUState)); });
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
  return guarded(instance, "fmi3FreeFMUState", allowed::FMUState, [&](Instance& s) {
    requireNonNull(FMUState, "FMUState");
    if (!*FMUState) return;  // nothing to free
    s.freeState(static_cast<Snapshot*>(*FMUState));
    *FMUState = nullptr;
  });
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t* size) {
  return guarded(instance, "fmi3SerializedFMUStateSize", allowed::FMUState, [&](Instance& s) {
    requireNonNull(size, "size");
    *size = s.serializeState(static_cast<const Snapshot*>(FMUState)).size();
  });
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
  return guarded(instance, "fmi3SerializeFMUState", allowed::FMUState, [&](Instance& s) {
    const auto bytes = s.serializeState(static_cast<const Snapshot*>(FMUState));
    require(size == bytes.size(), "size = " + std::to_string(size) + " but the serialized state has " +
                                      std::to_string(bytes.size()) + " bytes (fmi3SerializedFMUStateSize)");
    std::memcpy(array(serializedState, size, "serializedState").data(), bytes.data(), bytes.size());
  });
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState* FMUState) {
  return guarded(instance, "fmi3DeserializeFMUState", allowed::FMUState, [&](Instance& s) {
    requireNonNull(FMUState, "FMUState");
    *FMUState = s.deserializeState(array(serializedState, size, "serializedState"));
  });
}

/* Partial derivatives */

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                        const fmi3ValueReference[], size_t, const fmi3Float64[], size_t,
                                        fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetDirectionalDerivative",
                     "not offered (providesDirectionalDerivatives = false)");
}
fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                    const fmi3ValueReference[], size_t, const fmi3Float64[], size_t, fmi3Float64[],
                                    size_t) {
  return unsupported(instance, "fmi3GetAdjointDerivative", "not offered (providesAdjointDerivatives = false)");
}

/* Configuration Mode: structural parameters are fixed, so there is no Reconfiguration Mode. */

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
  return guarded(instance, "fmi3EnterConfigurationMode", allowed::EnterConfigurationMode,
                 [](Instance& s) { s.enterConfigurationMode(); });
}
fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
  return guarded(instance, "fmi3ExitConfigurationMode", allowed::ExitConfigurationMode,
                 [](Instance& s) { s.exitConfigurationMode(); });
}

/* Clocks and Event Mode */

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3Float64[],
                                  fmi3IntervalQualifier[]) {
  return unsupported(instance, "fmi3GetIntervalDecimal", kNoClocks);
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                   fmi3UInt64[], fmi3IntervalQualifier[]) {
  return unsupported(instance, "fmi3GetIntervalFraction", kNoClocks);
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3Float64[]) {
  return unsupported(instance, "fmi3GetShiftDecimal", kNoClocks);
}
fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                fmi3UInt64[]) {
  return unsupported(instance, "fmi3GetShiftFraction", kNoClocks);
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
  return unsupported(instance, "fmi3SetIntervalDecimal", kNoClocks);
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                   const fmi3UInt64[]) {
  return unsupported(instance, "fmi3SetIntervalFraction", kNoClocks);
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
  return unsupported(instance, "fmi3SetShiftDecimal", kNoClocks);
}
fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                const fmi3UInt64[]) {
  return unsupported(instance, "fmi3SetShiftFraction", kNoClocks);
}
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
  return unsupported(instance, "fmi3EvaluateDiscreteStates", kNoEventMode);
}
fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                                    fmi3Boolean*, fmi3Float64*) {
  return unsupported(instance, "fmi3UpdateDiscreteStates", kNoEventMode);
}

/* ---- Model Exchange ---- */

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
  return unsupported(instance, "fmi3EnterContinuousTimeMode", kModelExchange);
}
fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean, fmi3Boolean*, fmi3Boolean*) {
  return unsupported(instance, "fmi3CompletedIntegratorStep", kModelExchange);
}
fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64) {
  return unsupported(instance, "fmi3SetTime", kModelExchange);
}
fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3SetContinuousStates", kModelExchange);
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetContinuousStateDerivatives", kModelExchange);
}
fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetEventIndicators", kModelExchange);
}
fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetContinuousStates", kModelExchange);
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetNominalsOfContinuousStates", kModelExchange);
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t*) {
  return unsupported(instance, "fmi3GetNumberOfEventIndicators", kModelExchange);
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t*) {
  return unsupported(instance, "fmi3GetNumberOfContinuousStates", kModelExchange);
}

/* ---- Co-Simulation ---- */

fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
  return unsupported(instance, "fmi3EnterStepMode",
                     "PeriStep has no Event Mode to leave (hasEventMode = false): fmi3ExitInitializationMode "
                     "enters Step Mode directly");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Int32[],
                                    fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetOutputDerivatives", "not offered (maxOutputDerivativeOrder = 0)");
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean /*noSetFMUStatePriorToCurrentPoint*/,
                      fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation, fmi3Boolean* earlyReturn,
                      fmi3Float64* lastSuccessfulTime) {
  return guarded(instance, "fmi3DoStep", allowed::DoStep, [&](Instance& s) {
    requireNonNull(eventHandlingNeeded, "eventHandlingNeeded");
    requireNonNull(terminateSimulation, "terminateSimulation");
    requireNonNull(earlyReturn, "earlyReturn");
    requireNonNull(lastSuccessfulTime, "lastSuccessfulTime");
    *eventHandlingNeeded = fmi3False;
    *terminateSimulation = fmi3False;
    *earlyReturn = fmi3False;
    *lastSuccessfulTime = currentCommunicationPoint;
    const Instance::StepEnd end = s.doStep(currentCommunicationPoint, communicationStepSize);
    *lastSuccessfulTime = end.time;
    *terminateSimulation = end.testOver ? fmi3True : fmi3False;
  });
}

/* ---- Scheduled Execution ---- */

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference, fmi3Float64) {
  return unsupported(instance, "fmi3ActivateModelPartition",
                     "Scheduled Execution is not offered: PeriStep is a Co-Simulation FMU");
}

}  // extern "C"
