#pragma once
// SI prefixes for plots and labels: values are shown in the multiple of their unit that makes the
// largest of them a number between 0.1 and 100 (an opening of 3e-7 m is 0.3 µm, a crack 8e-4 m long
// 0.8 mm, 4e-9 m 4 nm rather than 0.004 µm, a toughness of 1.2e6 Pa.m^0.5 is 1.2 MPa.m^0.5). Units
// that do not start with a symbol that takes a prefix (none, kg/m3, m2) are left alone.
#include <string>

namespace peristep::host {

struct ScaledUnit {
  double factor = 1;  // shown value = value * factor
  std::string unit;   // the prefixed unit, e.g. "µm"; empty for a quantity without a unit
};

ScaledUnit scaledUnit(const std::string& unit, double largestMagnitude);

// "name [unit]", or the name alone without a unit.
std::string axisLabel(const std::string& name, const std::string& unit);

// A number with at most four significant digits ("80", "0.25", "1.2e+04").
std::string shortNumber(double v);

}  // namespace peristep::host
