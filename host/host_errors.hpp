#pragma once
// The host's two kinds of failure, told apart by exit code: the user can fix an InputError by
// editing a file or a command line (exit 2); a RunError happened while doing the work (exit 1).
#include <stdexcept>
#include <string>

namespace peristep::host {

// Missing or unreadable input, a malformed scene, an unknown variable, a bad command-line value.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The component refused a call (fmi3Error, with its logged message), or writing results failed.
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitRunError = 1;
inline constexpr int kExitInputError = 2;

}  // namespace peristep::host
