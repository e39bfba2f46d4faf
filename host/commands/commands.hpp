#pragma once
// The subcommands of `peristep`. Each returns the process exit code and throws InputError or
// RunError with a one-line message; main() prints it.
#include <string>

namespace peristep::host {

struct InfoOptions {
  std::string fmu;
};

struct RunOptions {
  std::string scene;  // empty: the built-in default scene (scenes/default.toml)
  std::string fmu;
  std::string out;    // overrides [output].file
  bool verbose = false;
};

struct ConvergenceOptions {
  std::string scene;
  std::string fmu;
  std::string out;    // overrides [output].csv; the plot goes next to it as .png
  bool verbose = false;
};

int infoCommand(const InfoOptions& options);
int runCommand(const RunOptions& options);
int convergenceCommand(const ConvergenceOptions& options);

}  // namespace peristep::host
