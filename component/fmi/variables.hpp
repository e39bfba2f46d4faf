#pragma once
// PeriStep's FMI variables: the variables several scenes share (scenes/shared_variables.hpp) followed by
// every scene's own (scenes/scene_declaration.hpp), and the enumeration types, with the `scene` items from
// the scene registry. modelDescription.xml, the documentation and api/peristep.h are generated from this
// table and the instance takes its start values from it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/variable_declaration.hpp"
#include "fmi3PlatformTypes.h"

namespace peristep::fmi {

using peristep::Bound;
using peristep::Causality;
using peristep::EnumerationItem;
using peristep::EnumerationType;
using peristep::Initial;
using peristep::UnitDefinition;
using peristep::Variability;
using peristep::Variable;
using peristep::VarType;

// Every variable, in the order of <ModelVariables> (structural parameters before the arrays they size).
const std::vector<Variable>& variables();
// nullptr for a value reference the model does not have.
const Variable* findVariable(fmi3ValueReference vr);

const std::vector<EnumerationType>& enumerationTypes();
const EnumerationType* findEnumeration(std::string_view name);

// <UnitDefinitions>: every unit a variable uses.
const std::vector<UnitDefinition>& unitDefinitions();

std::string_view typeName(VarType t);
std::string_view causalityName(Causality c);
std::string_view variabilityName(Variability v);
// "poissonRatio (vr 14)": how messages name a variable.
std::string label(const Variable& v);

}  // namespace peristep::fmi
