#pragma once
// Option parsing of the bench programs, as the host does it (CLI11): --help prints the usage and
// returns 0; an unknown option, a missing value or a value of the wrong type is an error (exit 2).
#include <CLI/CLI.hpp>

#include <optional>

namespace peristep::bench {

// The exit code if the program should stop here (help printed or a parse error), nullopt to go on.
inline std::optional<int> parseArguments(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  return std::nullopt;
}

}  // namespace peristep::bench
