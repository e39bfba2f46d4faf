#include "fmi/state_machine.hpp"

#include "fmi/parameter_values.hpp"

namespace peristep::fmi {

std::string setRefusal(const Variable& v, State s) {
  const std::string who = label(v);
  switch (v.causality) {
    case Causality::Independent:
      return who + " is the independent variable: only fmi3DoStep advances it";
    case Causality::CalculatedParameter:
    case Causality::Output:
      return who + " is " + (v.causality == Causality::Output ? "an output" : "a calculatedParameter") +
             " and cannot be set";
    case Causality::StructuralParameter:
      if (s == ConfigurationMode) return {};
      return who + " is a structural parameter: set it in Configuration Mode (fmi3EnterConfigurationMode from "
                   "Instantiated), not in " + std::string(stateName(s));
    case Causality::Parameter:
      if (s == Instantiated || s == InitializationMode) return {};
      if (s == ConfigurationMode) return who + " cannot be set in Configuration Mode, which accepts only structural parameters";
      return who + " is a fixed parameter and cannot change in " + std::string(stateName(s));
    case Causality::Input:
      if (s == ConfigurationMode) return who + " cannot be set in Configuration Mode, which accepts only structural parameters";
      return {};
  }
  return who + " cannot be set";
}

std::string getRefusal(const Variable& v, State s) {
  // Instantiated offers the start values (FMI 3.0 Sec. 2.3.2); computed values do not exist yet.
  if (s == Instantiated && !settable(v))
    return label(v) + " has no value before Initialization Mode (in Instantiated only variables with a start value "
                      "can be read)";
  return {};
}

}  // namespace peristep::fmi
