#pragma once
// A copy of everything that defines an instance's future (fmi3GetFMUState) and its byte form
// (fmi3SerializeFMUState): FMI state, time, stop time, every parameter and input value, whether
// the outputs match the inputs, and the scene model's own checkpoint when a model exists.
#include <cstdint>
#include <span>
#include <vector>

#include "fmi/parameter_values.hpp"
#include "fmi/state_machine.hpp"

namespace peristep::fmi {

struct Snapshot {
  State state = Instantiated;
  double time = 0;
  bool stopTimeDefined = false;
  double stopTime = 0;
  ParameterValues values;
  bool solutionValid = false;  // the outputs belong to the current inputs
  bool setSinceStep = false;   // Step Mode: a value was set after the last fmi3DoStep
  bool hasModel = false;
  std::vector<std::uint8_t> model;  // SceneModel::saveState() when hasModel
};

std::vector<std::uint8_t> serialize(const Snapshot& s);
// Throws InvalidInput("serialized FMU state is corrupt: ...") for bytes that are not a state of
// this PeriStep build (wrong magic, checksum, token or layout, values out of range, trailing bytes).
Snapshot deserialize(std::span<const std::uint8_t> bytes);

}  // namespace peristep::fmi
