#include "load_quantity.hpp"

#include <cmath>
#include <variant>

namespace peristep::host {

namespace {

const Attribute* attribute(const ResultLayout& layout, const std::string& name) {
  for (const Attribute& a : layout.parameterAttributes)
    if (a.name == name) return &a;
  return nullptr;
}

std::string text(const ResultLayout& layout, const std::string& name) {
  const Attribute* a = attribute(layout, name);
  const auto* s = a ? std::get_if<std::string>(&a->value) : nullptr;
  return s ? *s : "";
}

double number(const ResultLayout& layout, const std::string& name) {
  const Attribute* a = attribute(layout, name);
  const auto* v = a ? std::get_if<std::vector<double>>(&a->value) : nullptr;
  return v && v->size() == 1 ? v->front() : 0.0;
}

}  // namespace

LoadQuantity loadQuantity(const ResultLayout& layout, const std::string& inputUnit) {
  LoadQuantity plain{layout.inputName, inputUnit, 1.0, false};
  if (layout.inputName == "loadFactor" && text(layout, "scene") == "gamutBar" && text(layout, "gamutProtocol") == "cyclic")
    return {"step", "", 1.0, true};
  if (layout.inputName != "loadFactor" || text(layout, "scene") != "specimen") return plain;
  // The held grip that moves farthest at loadFactor 1 (grips moved in opposite directions, as the
  // glass-ceramic's bottom and top, are told by their names).
  const bool dynamic = text(layout, "specimenModel") == "dynamic";
  LoadQuantity best = plain;
  double largest = 0;
  for (const char* side : {"Left", "Right", "Bottom", "Top"}) {
    const std::string hold = text(layout, std::string("grip") + side);
    if (hold.empty() || hold == "free") continue;
    for (const char* component : {"x", "y"}) {
      if ((hold == "heldX" && *component == 'y') || (hold == "heldY" && *component == 'x')) continue;
      const std::string variable = std::string("grip") + side + (dynamic ? "V" : "U") + component;
      const double value = number(layout, variable);
      if (std::abs(value) <= largest) continue;
      largest = std::abs(value);
      std::string lower = side;
      lower[0] = static_cast<char>(lower[0] - 'A' + 'a');
      best = {lower + " grip " + (dynamic ? "velocity v" : "displacement u") + component, dynamic ? "m/s" : "m", value, false};
    }
  }
  return best;
}

}  // namespace peristep::host
