#include "unit_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace peristep::host {

namespace {

// The leading symbol of `unit` if it takes a prefix: "m" of "m/s", "Pa" of "Pa.m^0.5". Not when the
// symbol carries an exponent ("m2": a prefix would be squared with it) or is already prefixed ("kg").
std::string_view prefixable(std::string_view unit) {
  for (std::string_view symbol : {"Pa", "m", "s", "N", "J", "W"}) {
    if (unit.substr(0, symbol.size()) != symbol) continue;
    const std::string_view rest = unit.substr(symbol.size());
    if (rest.empty() || rest.front() == '/' || rest.front() == '.' || rest.front() == ' ') return symbol;
  }
  return {};
}

}  // namespace

ScaledUnit scaledUnit(const std::string& unit, double largestMagnitude) {
  const std::string_view symbol = prefixable(unit);
  if (symbol.empty() || !(largestMagnitude > 0) || !std::isfinite(largestMagnitude)) return {1.0, unit};
  static constexpr std::pair<int, const char*> kPrefixes[] = {{9, "G"},  {6, "M"},  {3, "k"},   {0, ""},
                                                             {-3, "m"}, {-6, "µ"}, {-9, "n"}, {-12, "p"}};
  // The largest value shown between 0.1 and 100 (with a rounding slack: 99.99999 um stays um).
  const int top = symbol == "s" ? 0 : 9;  // no kiloseconds
  int exponent = static_cast<int>(std::floor(std::log10(10 * largestMagnitude * (1 + 1e-9)) / 3.0)) * 3;
  exponent = std::clamp(exponent, -12, top);
  for (const auto& [e, prefix] : kPrefixes)
    if (e == exponent) return {std::pow(10.0, -e), prefix + unit};
  return {1.0, unit};
}

std::string axisLabel(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

std::string shortNumber(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

}  // namespace peristep::host
