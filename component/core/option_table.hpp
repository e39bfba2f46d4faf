#pragma once
// One table per option (linear solver, time integrator, ...): the C++ value that selects the code, the one
// name every interface spells it with (FMI enumeration item, scene file, command line) and a description.
// It is defined once, beside the code it selects; the FMI layer maps its enumeration values onto the C++
// values (scenes/enumeration_values.hpp) and takes names and descriptions from here.
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"

namespace peristep {

template <class Kind>
struct Option {
  Kind kind;
  std::string_view name;
  std::string_view description;
};

template <class Kind, std::size_t N>
const Option<Kind>& option(const std::array<Option<Kind>, N>& table, Kind kind) {
  const auto it = std::find_if(table.begin(), table.end(), [kind](const Option<Kind>& o) { return o.kind == kind; });
  if (it == table.end()) throw SolverFailure("internal error: an option missing from its table");
  return *it;
}

template <class Kind, std::size_t N>
std::vector<std::string> optionNames(const std::array<Option<Kind>, N>& table) {
  std::vector<std::string> names;
  for (const Option<Kind>& o : table) names.emplace_back(o.name);
  return names;
}

// The option a name stands for (command lines of the benches and tests); throws InvalidInput for an unknown
// name: "unknown <what> 'x' (known: a, b)".
template <class Kind, std::size_t N>
Kind optionKind(const std::array<Option<Kind>, N>& table, std::string_view name, std::string_view what) {
  const auto it = std::find_if(table.begin(), table.end(), [name](const Option<Kind>& o) { return o.name == name; });
  if (it != table.end()) return it->kind;
  std::string known;
  for (const Option<Kind>& o : table) known += (known.empty() ? "" : ", ") + std::string(o.name);
  throw InvalidInput("unknown " + std::string(what) + " '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace peristep
