#pragma once
// `--set name=value` on the command line: a [parameters] entry given or replaced before the scene is
// read, so a value from the command line passes every check a value in the file does (ranges, array
// lengths, structural parameters implied by arrays). The text is read as the variable's declared
// type: a number (Float32/64), an integer (Int*, UInt*), true or false (Boolean), an item name
// (Enumeration), a string otherwise; an array variable takes [a, b, ...] or a, b, ... .
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "model_description.hpp"
#include "scene_file.hpp"

namespace peristep::host {

// "name=value" split at the first '='. InputError without a name or an '='.
ParameterOverride parseOverride(const std::string& text);

// Writes every override into `parameters` (the scene's [parameters] table). InputError, naming the
// --set, for an unknown or unsettable variable or a value that does not read as its type.
void applyOverrides(toml::table& parameters, const std::vector<ParameterOverride>& overrides,
                    const ModelDescription& md);

}  // namespace peristep::host
