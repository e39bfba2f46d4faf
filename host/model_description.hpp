#pragma once
// What the host knows about a component: the contents of its modelDescription.xml (FMI 3.0), read
// with libxml2. The host maps every name in a scene file to a value reference through this, and
// never hard-codes a value reference.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace peristep::host {

enum class VarType {
  Float32, Float64, Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64,
  Boolean, String, Binary, Enumeration, Clock,
};

enum class Causality { Parameter, CalculatedParameter, StructuralParameter, Input, Output, Local, Independent };

enum class Variability { Constant, Fixed, Tunable, Discrete, Continuous };

std::string_view toString(VarType t);
std::string_view toString(Causality c);
std::string_view toString(Variability v);

// One <Dimension>: a fixed extent (start) or the value of a structural parameter (valueReference).
struct Dimension {
  std::optional<std::uint64_t> start;
  std::optional<std::uint32_t> valueReference;
};

struct Variable {
  std::string name;
  std::uint32_t valueReference = 0;
  VarType type = VarType::Float64;
  Causality causality = Causality::Local;
  Variability variability = Variability::Continuous;
  std::string initial;       // empty when not given
  std::string declaredType;  // the Enumeration's type name, or a Float64Type carrying the unit
  std::string unit;          // from the variable or its declared type
  std::string description;
  std::optional<std::string> start;  // raw text: space-separated for arrays
  std::vector<Dimension> dimensions;  // empty for a scalar

  bool isArray() const { return !dimensions.empty(); }
};

struct EnumerationItem {
  std::string name;
  std::int64_t value = 0;
  std::string description;
};

struct EnumerationType {
  std::string name;
  std::vector<EnumerationItem> items;

  const EnumerationItem* itemNamed(std::string_view item) const;
  const EnumerationItem* itemValued(std::int64_t value) const;
};

struct DefaultExperiment {
  std::optional<double> startTime, stopTime, tolerance, stepSize;
};

struct ModelDescription {
  std::string fmiVersion;
  std::string modelName;
  std::string instantiationToken;
  std::string description;
  std::string generationTool;
  std::string coSimulationIdentifier;  // empty when the FMU offers no Co-Simulation interface
  std::vector<Variable> variables;      // document order
  std::vector<EnumerationType> enumerations;
  std::vector<std::string> logCategories;
  DefaultExperiment defaultExperiment;

  const Variable* find(std::string_view name) const;
  const Variable* findByValueReference(std::uint32_t vr) const;
  const EnumerationType* enumeration(std::string_view typeName) const;
};

// Throws InputError naming the source and what is wrong (not well-formed, missing attribute, a
// Dimension that refers to no structural parameter, ...).
ModelDescription parseModelDescription(std::string_view xml, const std::string& sourceName);
ModelDescription readModelDescription(const std::filesystem::path& file);

}  // namespace peristep::host
