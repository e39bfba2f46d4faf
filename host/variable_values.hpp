#pragma once
// Values of one FMI variable in element order, held in the widest C type of its FMI type family.
#include <cstdint>
#include <variant>
#include <vector>

namespace peristep::host {

using Values = std::variant<std::vector<double>,         // Float32, Float64
                            std::vector<std::int64_t>,   // Int8..Int64, Enumeration
                            std::vector<std::uint64_t>,  // UInt8..UInt64
                            std::vector<bool>>;          // Boolean

inline std::size_t valueCount(const Values& v) {
  return std::visit([](const auto& vec) { return vec.size(); }, v);
}

}  // namespace peristep::host
