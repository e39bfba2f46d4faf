#pragma once
// Maps PeriStep's variables onto the scenes, the only file of the FMI layer that knows both: the
// SceneParameters a SceneModel is built from, and where every calculated parameter and output is read
// from (a scene's own parameters and outputs through its declaration, scenes/scene_declaration.hpp).
#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "fmi/parameter_values.hpp"
#include "scenes/scene_model.hpp"

namespace peristep::fmi {

SceneParameters sceneParameters(const ParameterValues& values);

// What has to exist before a computed variable can be read.
enum class Needs { Parameters, Model, Solution };

struct ComputedVariable {
  fmi3ValueReference vr;
  Needs needs;
  // The reader of the variable's type; writes every element (`model` is null only when needs is
  // Parameters).
  std::function<void(const ParameterValues&, const SceneModel*, std::span<double>)> readFloat64 = nullptr;
  std::function<void(const ParameterValues&, const SceneModel*, std::span<std::int32_t>)> readInt32 = nullptr;
  // Costly, computed on the first read (the exact moments): checked when read, not after every step.
  bool onRequest = false;
};

// nullptr for a variable that is not computed (parameters, inputs, the independent variable).
const ComputedVariable* findComputed(fmi3ValueReference vr);

// The first Float64 variable of `needs` (Model or Solution, not onRequest) whose value is not finite, as "name = inf" or
// "name[k] = nan"; empty when all are finite.
std::string firstNonFinite(const ParameterValues& values, const SceneModel& model, Needs needs);

}  // namespace peristep::fmi
