#pragma once
// " (did you mean nx?)" for a misspelt variable name, or "" when no name is close: messages about
// unknown names on the command line end with it.
#include <string>
#include <string_view>

#include "model_description.hpp"

namespace peristep::host {

// The closest variable name within two edits (insertions, deletions, substitutions), as a suffix.
std::string didYouMean(std::string_view name, const ModelDescription& md);

}  // namespace peristep::host
