#include "fmi/variables.hpp"

#include <algorithm>

#include "scenes/scene_declaration.hpp"
#include "scenes/shared_variables.hpp"

namespace peristep::fmi {

const std::vector<Variable>& variables() {
  static const std::vector<Variable> table = [] {
    std::vector<Variable> t = sharedVariables();
    for (const SceneDeclaration& scene : sceneDeclarations()) t.insert(t.end(), scene.variables.begin(), scene.variables.end());
    return t;
  }();
  return table;
}

const Variable* findVariable(fmi3ValueReference vr) {
  const auto& t = variables();
  const auto it = std::find_if(t.begin(), t.end(), [vr](const Variable& v) { return v.vr == vr; });
  return it == t.end() ? nullptr : &*it;
}

const std::vector<EnumerationType>& enumerationTypes() {
  static const std::vector<EnumerationType> types = [] {
    EnumerationType scenes{"PeriStep.Scene", "Built-in scenes", {}, "PERISTEP_SCENE_"};
    for (const SceneDeclaration& s : sceneDeclarations())
      scenes.items.push_back({s.name, static_cast<std::int64_t>(s.id), s.description});
    std::vector<EnumerationType> t{scenes};
    for (const EnumerationType& e : sharedEnumerations()) t.push_back(e);
    for (const SceneDeclaration& s : sceneDeclarations()) t.insert(t.end(), s.enumerations.begin(), s.enumerations.end());
    return t;
  }();
  return types;
}

const EnumerationType* findEnumeration(std::string_view name) {
  const auto& t = enumerationTypes();
  const auto it = std::find_if(t.begin(), t.end(), [name](const EnumerationType& e) { return e.name == name; });
  return it == t.end() ? nullptr : &*it;
}

const std::vector<UnitDefinition>& unitDefinitions() { return peristep::unitDefinitions(); }

std::string_view typeName(VarType t) {
  switch (t) {
    case VarType::Float64: return "Float64";
    case VarType::Int32: return "Int32";
    case VarType::UInt64: return "UInt64";
    case VarType::Enumeration: return "Enumeration";
  }
  return "?";
}

std::string_view causalityName(Causality c) {
  switch (c) {
    case Causality::Independent: return "independent";
    case Causality::StructuralParameter: return "structuralParameter";
    case Causality::Parameter: return "parameter";
    case Causality::CalculatedParameter: return "calculatedParameter";
    case Causality::Input: return "input";
    case Causality::Output: return "output";
  }
  return "?";
}

std::string_view variabilityName(Variability v) {
  switch (v) {
    case Variability::Fixed: return "fixed";
    case Variability::Discrete: return "discrete";
    case Variability::Continuous: return "continuous";
  }
  return "?";
}

std::string label(const Variable& v) { return std::string(v.name) + " (vr " + std::to_string(v.vr) + ")"; }

}  // namespace peristep::fmi
