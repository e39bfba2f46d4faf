#pragma once
// A scene as one unit: its enumeration item, its own parameters and outputs, how it reads them and how it
// is made. Every scene is one line of scenes/scene_registry.cpp; the FMI variable table, the enumerations,
// api/peristep.h, modelDescription.xml and the variable reference are generated from these declarations and
// the variables more than one scene reads (scenes/shared_variables.hpp).
#include <map>
#include <memory>
#include <string_view>
#include <vector>

#include "core/variable_declaration.hpp"
#include "scenes/scene_model.hpp"

namespace peristep {

class Runner;

// How one of the scene's own scalar outputs is read from its runner.
struct OwnOutput {
  ValueReference vr;
  double (*read)(const Runner& runner);
};

struct SceneDeclaration {
  SceneId id;                    // the value of its `scene` enumeration item
  std::string_view name;         // the item's name (scene files, modelDescription.xml)
  std::string_view description;  // the item's description: what it computes, the step sizes that fit
  // Its own parameters and outputs, with value references no other declaration uses; parameters arrive
  // in SceneParameters::own, outputs are read through `outputs`.
  std::vector<Variable> variables = {};
  std::vector<EnumerationType> enumerations = {};  // the types of its own enumeration parameters
  std::vector<OwnOutput> outputs = {};
  // Turns SceneParameters::own into the typed fields the scene reads (nullptr: it reads `own` itself).
  void (*configure)(SceneParameters& p) = nullptr;
  // Checks what only this scene reads; throws InvalidInput (nullptr: the scene is a specimen preset, checked
  // as a specimen by validate in scenes/scene_model.hpp).
  void (*validate)(const SceneParameters& p) = nullptr;
  // Builds the runner of validated parameters (scenes/scene_runner.hpp).
  std::unique_ptr<Runner> (*make)(const SceneParameters& p) = nullptr;
};

// Every scene, in the order of scenes/scene_registry.cpp.
const std::vector<SceneDeclaration>& sceneDeclarations();
// nullptr for an id no scene has.
const SceneDeclaration* findScene(SceneId id);

// A scalar of SceneParameters::own (its start value when the importer left it).
double ownValue(const SceneParameters& p, ValueReference vr);

}  // namespace peristep
