#pragma once
// How a scene declares the variables an importer sees: name, value reference, type, causality,
// variability, initial, unit, description, start value, array dimensions and admissible range. The scenes
// declare them (scenes/shared_variables.hpp, scenes/scene_declaration.hpp); the FMI layer assembles its
// table, modelDescription.xml, the documentation and api/peristep.h from those declarations.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace peristep {

using ValueReference = std::uint32_t;  // fmi3ValueReference

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
  ValueReference vr;
  VarType type;
  Causality causality;
  Variability variability;
  Initial initial;
  std::string_view description;
  std::string_view unit = {};          // empty: dimensionless
  std::string_view declaredType = {};  // the enumeration type of an Enumeration variable
  std::string_view start = {};         // empty: no start value; arrays: the value of every element
  std::vector<ValueReference> dimensions = {};  // structural parameters, outermost first
  std::optional<Bound> min = {};
  std::optional<Bound> max = {};
  // Outputs: the inputs the output depends on at a communication point (<Output dependencies>, FMI 3.0.2
  // Sec. 2.4.8); empty: none; unset: the attribute is omitted, meaning every known.
  std::optional<std::vector<ValueReference>> dependencies = {};
  std::string_view cName = {};  // its constant in api/peristep.h after PERISTEP_VR_; empty: NAME_IN_CAPITALS
};

struct EnumerationItem {
  std::string_view name;
  std::int64_t value;
  std::string_view description;
  std::string_view cName = {};  // its constant in api/peristep.h; empty: the type's cPrefix + NAME_IN_CAPITALS
};
struct EnumerationType {
  std::string_view name;
  std::string_view description;
  std::vector<EnumerationItem> items;
  std::string_view cPrefix;  // e.g. PERISTEP_GRIP_ for the items of PeriStep.Grip
};

// Short names for declaration tables: `using namespace peristep::declaration_names;` in the file that declares.
namespace declaration_names {
using C = Causality;
using V = Variability;
using I = Initial;
using T = VarType;
}  // namespace declaration_names

// A unit as powers of the SI base units (<UnitDefinitions>).
struct UnitDefinition {
  std::string_view name;
  int kg = 0, m = 0, s = 0;
  // <BaseUnit> exponents are integers: a unit with a half power (K_IC's m^(1/2)) is declared without one.
  bool integerPowers = true;
};

}  // namespace peristep
