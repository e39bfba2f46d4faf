#pragma once
// One FMU instance: FMI state, parameter and input values, the scene model built from them,
// simulation time and logger. Methods throw (InvalidInput for what the importer got wrong,
// SolverFailure for numerics, IllegalCall for the state machine); fmi3_functions.cpp turns that
// into fmi3Error plus exactly one log message. Instances share nothing, so they may run on
// different threads.
#include <cstdint>
#include <memory>
#include <string>
#include <span>
#include <string_view>
#include <vector>

#include "fmi/fmu_state.hpp"
#include "fmi/logging.hpp"
#include "fmi/parameter_values.hpp"
#include "fmi/state_machine.hpp"
#include "scenes/scene_model.hpp"

namespace peristep::fmi {

class Instance {
 public:
  Instance(Logger logger, std::string resourcePath);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  State state() const { return state_; }
  Logger& logger() { return logger_; }
  // Logs "<function>: <message>" as the one message of a failed call and enters Terminated, as
  // the standard requires after fmi3Error (FMI 3.0 Sec. 2.3.1).
  void fail(std::string_view function, std::string_view message) noexcept;

  void enterConfigurationMode();
  void exitConfigurationMode();
  void enterInitializationMode(double startTime, bool stopTimeDefined, double stopTime);
  // Builds the scene and solves at the current input (outputs at the start time).
  void exitInitializationMode();
  // Solves at the current input: the new time, and whether the scene's test is over (a fracture specimen
  // has split in two: fmi3DoStep's terminateSimulation).
  struct StepEnd {
    double time;
    bool testOver;
  };
  StepEnd doStep(double currentCommunicationPoint, double communicationStepSize);
  void terminate();
  // Back to Instantiated with every start value (FMU states stay valid).
  void reset();

  // T is the element type of one of the table's variable types; values has nValues elements.
  template <class T>
  void get(std::span<const fmi3ValueReference> vrs, std::span<T> values);
  template <class T>
  void set(std::span<const fmi3ValueReference> vrs, std::span<const T> values);
  // Getters and setters of types no variable has: every listed reference is an error.
  void refuseType(std::string_view type, std::span<const fmi3ValueReference> vrs, std::size_t nValues);

  // FMU states are owned by the instance; pointers that it did not hand out are rejected.
  Snapshot* saveState(Snapshot* reuse);
  void restoreState(const Snapshot* s);
  void freeState(Snapshot* s);
  std::vector<std::uint8_t> serializeState(const Snapshot* s) const;
  Snapshot* deserializeState(std::span<const std::uint8_t> bytes);

 private:
  const Snapshot& owned(const Snapshot* s) const;
  SceneModel& model();
  // The scene of `values` with this instance's progress messages.
  SceneParameters setUp(const ParameterValues& values) const;
  // At the current inputs: a quasi-static scene solves; a dynamic one integrates from time_ over
  // stepSize (0: outputs at time_, nothing integrated).
  void solve(double stepSize = 0);
  // Checks the listed references and returns their total element count.
  template <class T>
  std::size_t resolve(std::span<const fmi3ValueReference> vrs, bool forSet) const;

  Logger logger_;
  std::string resourcePath_;  // fmi3InstantiateCoSimulation's, possibly empty
  State state_ = Instantiated;
  ParameterValues values_;
  std::unique_ptr<SceneModel> model_;
  bool solutionValid_ = false;
  bool setSinceStep_ = false;
  double time_ = 0;
  bool stopTimeDefined_ = false;
  double stopTime_ = 0;
  std::vector<std::unique_ptr<Snapshot>> snapshots_;
};

}  // namespace peristep::fmi
