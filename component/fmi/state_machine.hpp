#pragma once
// The FMI 3.0 Co-Simulation state machine as PeriStep runs it (no Event Mode, no clocks, no
// tunable structural parameters): the states, the states in which each function may be called
// (a bitmask per function, as in the Reference FMUs), and which variables may be read or written in
// each state. The one check, requireState(), throws IllegalCall; fmi3_functions.cpp logs it.
#include <stdexcept>
#include <string>
#include <string_view>

#include "fmi/variables.hpp"

namespace peristep::fmi {

enum State : unsigned {
  Instantiated = 1u << 0,
  ConfigurationMode = 1u << 1,
  InitializationMode = 1u << 2,
  StepMode = 1u << 3,
  Terminated = 1u << 4,
};

constexpr unsigned kAnyState = Instantiated | ConfigurationMode | InitializationMode | StepMode | Terminated;

// Allowed states per function (FMI 3.0 Sec. 2.3 and 4.2). Every error moves the instance to
// Terminated (Sec. 2.3.1), from where only getters, FMU-state functions, fmi3Reset and
// fmi3FreeInstance remain.
namespace allowed {
constexpr unsigned SetDebugLogging = kAnyState;
constexpr unsigned Reset = kAnyState;
constexpr unsigned FMUState = kAnyState;  // get, set, free, serialize, deserialize
constexpr unsigned EnterConfigurationMode = Instantiated;
constexpr unsigned ExitConfigurationMode = ConfigurationMode;
constexpr unsigned EnterInitializationMode = Instantiated;
constexpr unsigned ExitInitializationMode = InitializationMode;
constexpr unsigned DoStep = StepMode;
constexpr unsigned Terminate = StepMode;
// Instantiated: start values only (see getRefusal); Configuration Mode only accepts structural parameters.
constexpr unsigned Get = Instantiated | InitializationMode | StepMode | Terminated;
constexpr unsigned Set = Instantiated | ConfigurationMode | InitializationMode | StepMode;
}  // namespace allowed

constexpr std::string_view stateName(State s) {
  switch (s) {
    case Instantiated: return "Instantiated";
    case ConfigurationMode: return "Configuration Mode";
    case InitializationMode: return "Initialization Mode";
    case StepMode: return "Step Mode";
    case Terminated: return "Terminated";
  }
  return "?";
}

struct IllegalCall : std::logic_error {
  using std::logic_error::logic_error;
};

inline void requireState(State current, unsigned allowedStates) {
  if (!(current & allowedStates)) throw IllegalCall("illegal call in state " + std::string(stateName(current)));
}

// Why v cannot be written in state s; empty when it can (FMI 3.0 Sec. 2.3.2-2.3.5, 4.2.1).
std::string setRefusal(const Variable& v, State s);
// Why v cannot be read in state s (a state allowed::Get admits); empty when it can.
std::string getRefusal(const Variable& v, State s);

}  // namespace peristep::fmi
