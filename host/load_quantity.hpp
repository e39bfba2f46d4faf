#pragma once
// What the ramped input of a run is physically, for plot axes and picture titles. The specimen scene's
// loadFactor moves every held grip to loadFactor times its displacement at 1 (gripTopUy, ...; the
// dynamic model: its velocity), so what is ramped is that grip's displacement, not a dimensionless
// factor; the gamut bar's cyclic protocol ignores its input (each step takes the protocol's next force
// step); other inputs (loadDisplacement, the smooth scenes' loadFactor) are what they say.
#include <string>

#include "result_layout.hpp"

namespace peristep::host {

struct LoadQuantity {
  std::string name;     // e.g. "loadDisplacement", "top grip displacement uy"
  std::string unit;     // of the quantity, e.g. "m"; empty for a factor
  double perInput = 1;  // quantity = perInput * input
  bool unused = false;  // the component ignores the input: plot against the step instead
};

// From the run's parameters (layout.parameterAttributes); inputUnit is the input variable's unit.
LoadQuantity loadQuantity(const ResultLayout& layout, const std::string& inputUnit);

}  // namespace peristep::host
