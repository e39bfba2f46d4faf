#include "hdf5_support.hpp"

#include <type_traits>

namespace peristep::host {

void writeAttribute(hid_t object, const Attribute& a) {
  std::visit(
      [&](const auto& v) {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) hdf5::writeString(object, a.name, v);
        else hdf5::writeNumbers(object, a.name, v);
      },
      a.value);
}

void describe(hid_t object, const ArrayInfo& info) {
  if (!info.unit.empty()) hdf5::writeString(object, "unit", info.unit);
  if (!info.description.empty()) hdf5::writeString(object, "description", info.description);
}

}  // namespace peristep::host
