#pragma once
// The component's identity as an importer sees it, defined once: the FMI functions, FMU states,
// modelDescription.xml, the documentation and the generated api/peristep.h take it from here.
#include <string_view>

namespace peristep::fmi {

inline constexpr std::string_view kModelIdentifier = "PeriStep";
// Changes when the variables change incompatibly: an importer built against other value references is refused.
inline constexpr std::string_view kInstantiationToken = "{8c4f2b7e-3d91-4a6c-b5e0-7f12a9d3c648}";

}  // namespace peristep::fmi
