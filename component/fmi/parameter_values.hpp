#pragma once
// The values an importer can set (structural parameters, parameters, inputs), element by element,
// starting from the variable table's start values. Every value is checked against its variable's
// type and admissible range before it is stored, so a stored set is always individually valid;
// cross-variable consistency (uniform spacing, enough random coordinates) is the scene's to check.
#include <algorithm>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "core/byte_stream.hpp"
#include "fmi/variables.hpp"

namespace peristep::fmi {

// The C element type of each variable type (what fmi3Get/Set<Type> transfers).
template <class T>
constexpr bool holds(VarType t) {
  if constexpr (std::is_same_v<T, double>) return t == VarType::Float64;
  if constexpr (std::is_same_v<T, std::int32_t>) return t == VarType::Int32;
  if constexpr (std::is_same_v<T, std::int64_t>) return t == VarType::Enumeration;
  if constexpr (std::is_same_v<T, std::uint64_t>) return t == VarType::UInt64;
  return false;
}

// Whether the importer can ever set the variable (its causality allows a start value).
bool settable(const Variable& v);

class ParameterValues {
 public:
  ParameterValues();  // the start values of every settable variable

  // Elements of v for the current structural parameters (1 for a scalar).
  std::size_t size(const Variable& v) const;

  template <class T>
  std::span<const T> get(fmi3ValueReference vr) const;
  template <class T>
  T scalar(fmi3ValueReference vr) const { return get<T>(vr)[0]; }

  // Throws InvalidInput naming the variable and the admissible range for the first bad value.
  template <class T>
  void check(const Variable& v, std::span<const T> values) const;
  // Stores checked values; returns whether anything changed. A structural parameter resizes the
  // arrays it dimensions (kept elements keep their values, new ones take the start value).
  template <class T>
  bool set(const Variable& v, std::span<const T> values);

  // Equal in every variable except the inputs: the same scene set-up.
  bool sameSetUp(const ParameterValues& other) const;

  void write(ByteWriter& out) const;
  static ParameterValues read(ByteReader& in);

 private:
  using Slot = std::variant<std::vector<double>, std::vector<std::int32_t>, std::vector<std::int64_t>,
                            std::vector<std::uint64_t>>;
  void resizeArraysOf(fmi3ValueReference structural);
  std::map<fmi3ValueReference, Slot> slots_;
};

}  // namespace peristep::fmi
