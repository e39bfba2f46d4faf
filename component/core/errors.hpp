#pragma once
// Errors raised inside the solver library. The FMI layer turns them into fmi3Error plus one log
// message; nothing here may terminate the process.
#include <stdexcept>
#include <string>

namespace peristep {

// Input that is non-physical or inconsistent (E <= 0, nu >= 0.5, delta < h, empty domain, ...).
struct InvalidInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A numerical step that could not be completed (singular factorization, no convergence, NaN).
struct SolverFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Always-on check for user input: throws InvalidInput with the message when cond is false.
inline void require(bool cond, const std::string& message) {
  if (!cond) throw InvalidInput(message);
}

}  // namespace peristep
