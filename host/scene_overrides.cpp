#include "scene_overrides.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <variant>

#include "host_errors.hpp"
#include "name_suggestion.hpp"

namespace peristep::host {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::string described(const ParameterOverride& o) { return "--set " + o.name + "=" + o.value; }

[[noreturn]] void refuse(const ParameterOverride& o, const std::string& problem) {
  throw InputError(described(o) + ": " + problem);
}

bool isFloat(VarType t) { return t == VarType::Float32 || t == VarType::Float64; }
bool isInteger(VarType t) {
  return t == VarType::Int8 || t == VarType::UInt8 || t == VarType::Int16 || t == VarType::UInt16 ||
         t == VarType::Int32 || t == VarType::UInt32 || t == VarType::Int64 || t == VarType::UInt64;
}

bool isUnsigned(VarType t) {
  return t == VarType::UInt8 || t == VarType::UInt16 || t == VarType::UInt32 || t == VarType::UInt64;
}

std::string itemList(const EnumerationType& e) {
  std::string list;
  for (const EnumerationItem& i : e.items) list += (list.empty() ? "" : ", ") + i.name;
  return list;
}

using Element = std::variant<double, std::int64_t, bool, std::string>;

// One element as the TOML value the scene reader expects for the variable's type. Integers out of a
// type's range are left to the scene reader, which names the range.
Element element(const ParameterOverride& o, const Variable& var, const std::string& text,
                       const ModelDescription& md) {
  const std::string expected = " for " + std::string(toString(var.type)) + ", got \"" + text + "\"";
  if (isFloat(var.type)) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || errno == ERANGE) refuse(o, "expected a finite number" + expected);
    return v;
  }
  if (isInteger(var.type)) {
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE) refuse(o, "expected an integer" + expected);
    if (v < 0 && isUnsigned(var.type)) refuse(o, "expected a non-negative integer" + expected);
    return static_cast<std::int64_t>(v);
  }
  if (var.type == VarType::Boolean) {
    if (text == "true" || text == "1") return true;
    if (text == "false" || text == "0") return false;
    refuse(o, "expected true or false" + expected);
  }
  if (var.type == VarType::Enumeration) {
    const EnumerationType* e = md.enumeration(var.declaredType);
    if (e && !e->itemNamed(text))
      refuse(o, "unknown item \"" + text + "\" of " + e->name + " (expected one of: " + itemList(*e) + ")");
  }
  return text;
}

}  // namespace

ParameterOverride parseOverride(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) throw InputError("--set " + text + ": expected name=value");
  ParameterOverride o{trimmed(text.substr(0, eq)), trimmed(text.substr(eq + 1))};
  if (o.name.empty()) throw InputError("--set " + text + ": expected name=value, the name is missing");
  return o;
}

void applyOverrides(toml::table& parameters, const std::vector<ParameterOverride>& overrides,
                    const ModelDescription& md) {
  for (const ParameterOverride& o : overrides) {
    const Variable* var = md.find(o.name);
    if (!var)
      refuse(o, "unknown variable: " + md.modelName + "'s model description has no variable of that name" +
                    didYouMean(o.name, md) + "; peristep info lists them");
    const bool settable = var->causality == Causality::Parameter || var->causality == Causality::StructuralParameter ||
                          var->causality == Causality::Input;
    if (!settable || var->variability == Variability::Constant)
      refuse(o, o.name + " is a " + std::string(toString(var->variability)) + " " +
                    std::string(toString(var->causality)) + " and cannot be set");
    if (!var->isArray()) {
      std::visit([&](const auto& v) { parameters.insert_or_assign(o.name, v); }, element(o, *var, o.value, md));
      continue;
    }
    std::string list = o.value;  // [a, b, c] or a, b, c
    if (list.size() >= 2 && list.front() == '[' && list.back() == ']') list = list.substr(1, list.size() - 2);
    toml::array values;
    std::size_t start = 0;
    while (start <= list.size()) {
      const std::size_t comma = std::min(list.find(',', start), list.size());
      std::visit([&](const auto& v) { values.push_back(v); }, element(o, *var, trimmed(list.substr(start, comma - start)), md));
      start = comma + 1;
    }
    parameters.insert_or_assign(o.name, std::move(values));
  }
}

}  // namespace peristep::host
