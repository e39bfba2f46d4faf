#pragma once
// scenes/default.toml, compiled in at build time: what `peristep run` does without a scene file.
#include <string_view>

namespace peristep::host {

std::string_view defaultSceneText();

}  // namespace peristep::host
