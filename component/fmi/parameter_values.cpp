#include "fmi/parameter_values.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"

namespace peristep::fmi {

namespace {

template <class T>
T parseStart(const Variable& v) {
  T value{};
  const char* end = v.start.data() + v.start.size();
  const auto [p, ec] = std::from_chars(v.start.data(), end, value);
  if (ec != std::errc() || p != end) throw std::logic_error("variable table: bad start value of " + label(v));
  return value;
}

template <class T>
std::string text(T x) {
  if constexpr (std::is_floating_point_v<T>) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
  } else {
    return std::to_string(x);
  }
}

std::string rangeText(const Variable& v) {
  std::string s = v.min ? (v.min->open ? "(" : "[") : "(";
  s += v.min ? text(v.min->value) : "-inf";
  s += ", ";
  s += v.max ? text(v.max->value) : "inf";
  s += v.max && !v.max->open ? "]" : ")";
  return s;
}

bool inRange(const Variable& v, double x) {
  if (v.min && (v.min->open ? x <= v.min->value : x < v.min->value)) return false;
  if (v.max && (v.max->open ? x >= v.max->value : x > v.max->value)) return false;
  return true;
}

std::string enumerationText(const EnumerationType& e) {
  std::string s;
  for (const auto& item : e.items) s += (s.empty() ? "" : ", ") + std::to_string(item.value) + " " + std::string(item.name);
  return s;
}

// Calls f with a typed tag for the element type of variable type t.
template <class F>
decltype(auto) withElementType(VarType t, F&& f) {
  switch (t) {
    case VarType::Float64: return f(double{});
    case VarType::Int32: return f(std::int32_t{});
    case VarType::Enumeration: return f(std::int64_t{});
    case VarType::UInt64: return f(std::uint64_t{});
  }
  throw std::logic_error("unknown variable type");
}

}  // namespace

bool settable(const Variable& v) {
  return v.causality == Causality::StructuralParameter || v.causality == Causality::Parameter ||
         v.causality == Causality::Input;
}

ParameterValues::ParameterValues() {
  // Structural parameters first: they size the arrays.
  for (int pass = 0; pass < 2; ++pass)
    for (const Variable& v : variables()) {
      if (!settable(v) || (v.causality == Causality::StructuralParameter) != (pass == 0)) continue;
      withElementType(v.type, [&](auto tag) {
        using T = decltype(tag);
        slots_[v.vr] = std::vector<T>(size(v), parseStart<T>(v));
      });
    }
}

std::size_t ParameterValues::size(const Variable& v) const {
  std::size_t n = 1;
  for (fmi3ValueReference d : v.dimensions) n *= static_cast<std::size_t>(scalar<std::uint64_t>(d));
  return n;
}

template <class T>
std::span<const T> ParameterValues::get(fmi3ValueReference vr) const {
  return std::get<std::vector<T>>(slots_.at(vr));
}

template <class T>
void ParameterValues::check(const Variable& v, std::span<const T> values) const {
  for (std::size_t i = 0; i < values.size(); ++i) {
    const T x = values[i];
    std::string who = label(v);
    if (!v.dimensions.empty()) who.append("[").append(std::to_string(i)).append("]");
    if constexpr (std::is_floating_point_v<T>)
      require(std::isfinite(x), who + " must be finite, got " + text(x));
    if (v.type == VarType::Enumeration) {
      const EnumerationType* e = findEnumeration(v.declaredType);
      bool known = false;
      for (const auto& item : e->items) known = known || item.value == static_cast<std::int64_t>(x);
      require(known, who + " = " + text(x) + " is not a value of " + std::string(e->name) + " (" +
                         enumerationText(*e) + ")");
    }
    require(inRange(v, static_cast<double>(x)), who + " must lie in " + rangeText(v) + ", got " + text(x));
  }
}

template <class T>
bool ParameterValues::set(const Variable& v, std::span<const T> values) {
  auto& stored = std::get<std::vector<T>>(slots_.at(v.vr));
  if (std::equal(stored.begin(), stored.end(), values.begin(), values.end())) return false;
  stored.assign(values.begin(), values.end());
  if (v.causality == Causality::StructuralParameter) resizeArraysOf(v.vr);
  return true;
}

void ParameterValues::resizeArraysOf(fmi3ValueReference structural) {
  for (const Variable& v : variables()) {
    if (!settable(v) || std::find(v.dimensions.begin(), v.dimensions.end(), structural) == v.dimensions.end())
      continue;
    std::visit(
        [&](auto& stored) {
          using T = typename std::decay_t<decltype(stored)>::value_type;
          stored.resize(size(v), parseStart<T>(v));
        },
        slots_.at(v.vr));
  }
}

bool ParameterValues::sameSetUp(const ParameterValues& other) const {
  for (const auto& [vr, slot] : slots_)
    if (findVariable(vr)->causality != Causality::Input && slot != other.slots_.at(vr)) return false;
  return true;
}

void ParameterValues::write(ByteWriter& out) const {
  out.put<std::uint64_t>(slots_.size());
  for (const auto& [vr, slot] : slots_) {
    out.put<std::uint32_t>(vr);
    out.put<std::uint8_t>(static_cast<std::uint8_t>(slot.index()));
    std::visit([&](const auto& stored) { out.putArray(std::span(stored)); }, slot);
  }
}

ParameterValues ParameterValues::read(ByteReader& in) {
  ParameterValues p;  // every settable variable, at its start value
  const auto count = in.get<std::uint64_t>();
  if (count != p.slots_.size())
    ByteReader::corrupt("it holds " + std::to_string(count) + " parameter values, expected " +
                        std::to_string(p.slots_.size()));
  std::map<fmi3ValueReference, Slot> read;
  for (std::uint64_t k = 0; k < count; ++k) {
    const auto vr = in.get<fmi3ValueReference>();
    const auto index = in.get<std::uint8_t>();
    const auto it = p.slots_.find(vr);
    if (it == p.slots_.end() || index != it->second.index() || read.count(vr))
      ByteReader::corrupt("unexpected entry for value reference " + std::to_string(vr));
    std::visit([&](const auto& start) {
      using T = typename std::decay_t<decltype(start)>::value_type;
      read[vr] = in.getArray<T>();
    }, it->second);
  }
  p.slots_ = std::move(read);
  // Re-check as if the importer had set the values: structure first, then sizes and ranges.
  try {
    for (const Variable& v : variables()) {
      if (!settable(v)) continue;
      std::visit([&](const auto& stored) {
        using T = typename std::decay_t<decltype(stored)>::value_type;
        if (stored.size() != p.size(v)) ByteReader::corrupt(label(v) + " has the wrong number of elements");
        p.check(v, std::span<const T>(stored));
      }, p.slots_.at(v.vr));
    }
  } catch (const InvalidInput& e) {
    if (std::string_view(e.what()).starts_with("serialized FMU state")) throw;
    ByteReader::corrupt(e.what());
  }
  return p;
}

#define PERISTEP_FMI_INSTANTIATE(T)                                                            \
  template std::span<const T> ParameterValues::get<T>(fmi3ValueReference) const;               \
  template void ParameterValues::check<T>(const Variable&, std::span<const T>) const;          \
  template bool ParameterValues::set<T>(const Variable&, std::span<const T>);
PERISTEP_FMI_INSTANTIATE(double)
PERISTEP_FMI_INSTANTIATE(std::int32_t)
PERISTEP_FMI_INSTANTIATE(std::int64_t)
PERISTEP_FMI_INSTANTIATE(std::uint64_t)
#undef PERISTEP_FMI_INSTANTIATE

}  // namespace peristep::fmi
