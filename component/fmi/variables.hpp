#pragma once
// The single source of truth for PeriStep's FMI variables: name, value reference, type, causality,
// variability, initial, unit, description, start value, array dimensions and admissible range.
// modelDescription.xml is generated from this table and the instance takes its start values from
// it. Value references come from api/peristep.h, which importers use.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fmi3PlatformTypes.h"

namespace peristep::fmi {

// Enumeration variables are read and written with fmi3GetInt64/fmi3SetInt64 (FMI 3.0 Sec. 2.4.7.5).
enum class VarType { Float64, Int32, UInt64, Enumeration };
enum class Causality { Independent, StructuralParameter, Parameter, CalculatedParameter, Input, Output };
// Continuous only for Float64 (FMI 3.0.2 Sec. 2.4.7.4); outputs of other types are Discrete.
enum class Variability { Fixed, Discrete, Continuous };
// Default: the attribute is omitted (inputs and the independent variable may not carry it).
enum class Initial { Default, Exact, Calculated };

// One end of an admissible interval; open ends exclude the value itself.
struct Bound {
  double value;
  bool open = false;
};

struct Variable {
  std::string_view name;
  fmi3ValueReference vr;
  VarType type;
  Causality causality;
  Variability variability;
  Initial initial;
  std::string_view description;
  std::string_view unit = {};          // empty: dimensionless
  std::string_view declaredType = {};  // the enumeration type of an Enumeration variable
  std::string_view start = {};         // empty: no start value; arrays: the value of every element
  std::vector<fmi3ValueReference> dimensions = {};  // structural parameters, outermost first
  std::optional<Bound> min = {};
  std::optional<Bound> max = {};
  // Outputs: the inputs the output depends on at a communication point (<Output dependencies>, FMI 3.0.2
  // Sec. 2.4.8); empty: none; unset: the attribute is omitted, meaning every known.
  std::optional<std::vector<fmi3ValueReference>> dependencies = {};
};

// Every variable, in the order of <ModelVariables> (structural parameters before the arrays they size).
const std::vector<Variable>& variables();
// nullptr for a value reference the model does not have.
const Variable* findVariable(fmi3ValueReference vr);

struct EnumerationItem {
  std::string_view name;
  std::int64_t value;
  std::string_view description;
};
struct EnumerationType {
  std::string_view name;
  std::string_view description;
  std::vector<EnumerationItem> items;
};
const std::vector<EnumerationType>& enumerationTypes();
const EnumerationType* findEnumeration(std::string_view name);

// A unit as powers of the SI base units (<UnitDefinitions>).
struct UnitDefinition {
  std::string_view name;
  int kg = 0, m = 0, s = 0;
  // <BaseUnit> exponents are integers: a unit with a half power (K_IC's m^(1/2)) is declared without one.
  bool integerPowers = true;
};
const std::vector<UnitDefinition>& unitDefinitions();

std::string_view typeName(VarType t);
std::string_view causalityName(Causality c);
std::string_view variabilityName(Variability v);
// "poissonRatio (vr 14)": how messages name a variable.
std::string label(const Variable& v);

}  // namespace peristep::fmi
