#pragma once
// The subcommands of `peristep`. Each returns the process exit code and throws InputError or
// RunError with a one-line message; main() prints it.
#include <cstdint>
#include <string>
#include <vector>

namespace peristep::host {

struct InfoOptions {
  std::string fmu;
  std::string name;  // a variable or scene to show in full; empty: the summary of all
};

struct RunOptions {
  std::string scene;  // empty: the built-in default scene (scenes/default.toml)
  std::string fmu;
  std::string out;    // overrides [output].file
  std::vector<std::string> set;  // --set name=value, in order
  bool verbose = false;
};

struct ConvergenceOptions {
  std::string scene;
  std::string fmu;
  std::string out;    // overrides [output].csv; the plot goes next to it as .png
  std::vector<std::string> set;  // --set name=value, in order
  bool verbose = false;
};

struct SampleOptions {
  std::string scene;
  std::string fmu;
  std::string out;                     // HDF5 study file; CSV and sample directory beside it
  std::string rule;                    // tensor | smolyak | mc | mlmc
  std::vector<std::uint64_t> levels;   // tensor: points per coordinate; smolyak: level
  std::vector<std::uint64_t> samples;  // mc: sample counts
  bool nested = false;
  std::uint64_t seed = 1;
  std::vector<std::string> set;        // --set name=value, in order
  bool verbose = false;
  std::string shard;                   // "K/N": run only the K-th of N parts, write only samples
  bool merge = false;                  // no sample run: statistics and files from the stored samples
  // mlmc (multilevel_study.hpp)
  std::size_t grids = 3;
  std::string quantity;                // default: the scene's first [output] result, else toughnessKIC
  double se = 0.02, seAbsolute = 0;
  std::size_t pilot = 10;
  std::vector<double> levelCosts;
};

int infoCommand(const InfoOptions& options);
int runCommand(const RunOptions& options);
int convergenceCommand(const ConvergenceOptions& options);
int sampleCommand(const SampleOptions& options);

}  // namespace peristep::host
