#pragma once
// What the ABI tests share: PeriStep.so opened with dlopen() and every FMI 3.0 function resolved by
// name (as an importer does; the tests call nothing else), a logger that records each instance's
// messages, and a small RAII session around one instance.
#include <dlfcn.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmi3FunctionTypes.h"
#include "peristep.h"

// Every function of the FMI 3.0 standard.
#define PERISTEP_FMI3_FUNCTIONS(X)                                                                            \
  X(fmi3GetVersion) X(fmi3SetDebugLogging) X(fmi3InstantiateModelExchange) X(fmi3InstantiateCoSimulation)     \
  X(fmi3InstantiateScheduledExecution) X(fmi3FreeInstance) X(fmi3EnterInitializationMode)                     \
  X(fmi3ExitInitializationMode) X(fmi3EnterEventMode) X(fmi3Terminate) X(fmi3Reset) X(fmi3GetFloat32)         \
  X(fmi3GetFloat64) X(fmi3GetInt8) X(fmi3GetUInt8) X(fmi3GetInt16) X(fmi3GetUInt16) X(fmi3GetInt32)           \
  X(fmi3GetUInt32) X(fmi3GetInt64) X(fmi3GetUInt64) X(fmi3GetBoolean) X(fmi3GetString) X(fmi3GetBinary)       \
  X(fmi3GetClock) X(fmi3SetFloat32) X(fmi3SetFloat64) X(fmi3SetInt8) X(fmi3SetUInt8) X(fmi3SetInt16)          \
  X(fmi3SetUInt16) X(fmi3SetInt32) X(fmi3SetUInt32) X(fmi3SetInt64) X(fmi3SetUInt64) X(fmi3SetBoolean)        \
  X(fmi3SetString) X(fmi3SetBinary) X(fmi3SetClock) X(fmi3GetNumberOfVariableDependencies)                    \
  X(fmi3GetVariableDependencies) X(fmi3GetFMUState) X(fmi3SetFMUState) X(fmi3FreeFMUState)                    \
  X(fmi3SerializedFMUStateSize) X(fmi3SerializeFMUState) X(fmi3DeserializeFMUState)                          \
  X(fmi3GetDirectionalDerivative) X(fmi3GetAdjointDerivative) X(fmi3EnterConfigurationMode)                   \
  X(fmi3ExitConfigurationMode) X(fmi3GetIntervalDecimal) X(fmi3GetIntervalFraction) X(fmi3GetShiftDecimal)    \
  X(fmi3GetShiftFraction) X(fmi3SetIntervalDecimal) X(fmi3SetIntervalFraction) X(fmi3SetShiftDecimal)         \
  X(fmi3SetShiftFraction) X(fmi3EvaluateDiscreteStates) X(fmi3UpdateDiscreteStates)                           \
  X(fmi3EnterContinuousTimeMode) X(fmi3CompletedIntegratorStep) X(fmi3SetTime) X(fmi3SetContinuousStates)     \
  X(fmi3GetContinuousStateDerivatives) X(fmi3GetEventIndicators) X(fmi3GetContinuousStates)                   \
  X(fmi3GetNominalsOfContinuousStates) X(fmi3GetNumberOfEventIndicators) X(fmi3GetNumberOfContinuousStates)   \
  X(fmi3EnterStepMode) X(fmi3GetOutputDerivatives) X(fmi3DoStep) X(fmi3ActivateModelPartition)

struct Fmu {
#define PERISTEP_DECLARE(name) name##TYPE* name = nullptr;
  PERISTEP_FMI3_FUNCTIONS(PERISTEP_DECLARE)
#undef PERISTEP_DECLARE

  // Opened once per test process; throws naming the first function that is not exported.
  static const Fmu& get() {
    static const Fmu fmu(PERISTEP_SO_PATH);
    return fmu;
  }

 private:
  explicit Fmu(const char* path) {
    void* library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!library) throw std::runtime_error(std::string("dlopen: ") + dlerror());
#define PERISTEP_RESOLVE(name)                                                                 \
  name = reinterpret_cast<name##TYPE*>(dlsym(library, #name));                                \
  if (!name) throw std::runtime_error(std::string(#name) + " is not exported by " + path);
    PERISTEP_FMI3_FUNCTIONS(PERISTEP_RESOLVE)
#undef PERISTEP_RESOLVE
  }
};

struct LogRecord {
  fmi3Status status;
  std::string category, message;
};

// Passed as the instance environment: the FMU hands it back with every message.
struct LogRecorder {
  std::vector<LogRecord> records;
  std::size_t errors() const {
    std::size_t n = 0;
    for (const auto& r : records) n += r.status == fmi3Error;
    return n;
  }
  void clear() { records.clear(); }
};

inline void recordMessage(fmi3InstanceEnvironment environment, fmi3Status status, fmi3String category,
                          fmi3String message) {
  static_cast<LogRecorder*>(environment)->records.push_back({status, category ? category : "", message});
}

// One co-simulation instance with its own log; freed on destruction.
class Session {
 public:
  explicit Session(bool loggingOn = true, const char* resourcePath = PERISTEP_RESOURCES_PATH)
      : fmu(Fmu::get()),
        instance(fmu.fmi3InstantiateCoSimulation("abi", PERISTEP_INSTANTIATION_TOKEN, resourcePath, fmi3False, loggingOn,
                                                 fmi3False, fmi3False, nullptr, 0, &log, recordMessage, nullptr)) {
    if (!instance) throw std::runtime_error("instantiation failed");
  }
  ~Session() { fmu.fmi3FreeInstance(instance); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Configuration Mode round trip for the structural parameters.
  fmi3Status configure(std::uint64_t nx, std::uint64_t ny, std::uint64_t nModes = 1) {
    return configureStructural({PERISTEP_VR_NX, PERISTEP_VR_NY, PERISTEP_VR_NMODES}, {nx, ny, nModes});
  }
  fmi3Status configureStructural(const std::vector<fmi3ValueReference>& vrs, const std::vector<fmi3UInt64>& values) {
    if (const auto s = fmu.fmi3EnterConfigurationMode(instance); s != fmi3OK) return s;
    if (const auto s = fmu.fmi3SetUInt64(instance, vrs.data(), vrs.size(), values.data(), values.size()); s != fmi3OK)
      return s;
    return fmu.fmi3ExitConfigurationMode(instance);
  }
  fmi3Status setFloat64(fmi3ValueReference vr, std::vector<double> values) {
    return fmu.fmi3SetFloat64(instance, &vr, 1, values.data(), values.size());
  }
  fmi3Status setInt64(fmi3ValueReference vr, std::int64_t value) {
    return fmu.fmi3SetInt64(instance, &vr, 1, &value, 1);
  }
  // Reads n elements of one Float64 variable; returns an empty vector when the call fails.
  fmi3Status setUInt64(fmi3ValueReference vr, std::uint64_t value) {
    return fmu.fmi3SetUInt64(instance, &vr, 1, &value, 1);
  }
  // The bytes of a serialized FMU state; empty when a call fails.
  std::vector<fmi3Byte> serialize(fmi3FMUState state) {
    std::size_t size = 0;
    if (fmu.fmi3SerializedFMUStateSize(instance, state, &size) != fmi3OK) return {};
    std::vector<fmi3Byte> bytes(size);
    if (fmu.fmi3SerializeFMUState(instance, state, bytes.data(), bytes.size()) != fmi3OK) return {};
    return bytes;
  }
  std::vector<double> getFloat64(fmi3ValueReference vr, std::size_t n = 1) {
    std::vector<double> v(n);
    if (fmu.fmi3GetFloat64(instance, &vr, 1, v.data(), n) != fmi3OK) v.clear();
    return v;
  }
  fmi3Status initialize(double startTime = 0, double stopTime = 1) {
    if (const auto s = fmu.fmi3EnterInitializationMode(instance, fmi3False, 0, startTime, fmi3True, stopTime);
        s != fmi3OK)
      return s;
    return fmu.fmi3ExitInitializationMode(instance);
  }
  fmi3Status step(double t, double h, double* lastSuccessfulTime = nullptr) {
    fmi3Boolean event = fmi3True, terminate = fmi3True, early = fmi3True;
    fmi3Float64 last = -1;
    const fmi3Status s = fmu.fmi3DoStep(instance, t, h, fmi3False, &event, &terminate, &early, &last);
    if (s == fmi3OK && (event || early)) throw std::runtime_error("fmi3DoStep raised a flag");
    testOver = s == fmi3OK && terminate;
    if (lastSuccessfulTime) *lastSuccessfulTime = last;
    return s;
  }

  const Fmu& fmu;
  LogRecorder log;
  fmi3Instance instance;
  bool testOver = false;  // the last fmi3DoStep set terminateSimulation (a fracture specimen has split)
};
