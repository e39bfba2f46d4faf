#pragma once
// A scene file (TOML) names variables of the model description and says how to load the component:
//
//   [parameters]   name = value     numbers, integers, arrays for array variables (xi = [0.5]),
//                                   enumeration items by name (scene = "smooth")
//   [loading]      input = "loadFactor", from = 0.0, to = 1.0, steps = 4, startTime = 0.0, stopTime = 1.0
//   [output]       file = "run.h5"  (HDF5 written by `peristep run`), csv = "study.csv" (`peristep convergence`),
//                  results = ["toughnessKIC"]  (scalar outputs whose distribution `peristep sample` draws)
//   [convergence]  levels = [8, 16, 32, 64]   (nx = ny = level + 1)
//
// Everything is checked against the model description while parsing, so a scene that parses can
// be applied to the component without a name or type error. Problems throw InputError with one
// line "file:line: [table] key: problem".
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model_description.hpp"
#include "variable_values.hpp"

namespace peristep::host {

struct Setting {
  Variable variable;
  Values values;
};

// One fmi3DoStep per increment; increment k of n (k = 1..n) holds the input at from + k (to - from) / n.
struct Loading {
  std::optional<Variable> input;  // none: the component's inputs keep their start values
  double from = 0, to = 0;
  std::uint64_t steps = 1;
  double startTime = 0, stopTime = 1;
};

struct Scene {
  std::string source;              // file name (or "<built-in default scene>") for messages
  std::vector<Setting> parameters; // file order, plus structural parameters implied by array lengths
  Loading loading;
  std::string outputFile;          // [output].file, empty when not given
  std::string csvFile;             // [output].csv, empty when not given
  std::vector<std::string> results;  // [output].results: scalar Float64 outputs, empty when not given
  std::vector<std::uint64_t> levels;  // [convergence].levels, empty when not given

  const Setting* setting(std::string_view name) const;
};

// `--set name=value` from the command line (scene_overrides.hpp): replaces or adds a [parameters] entry.
struct ParameterOverride {
  std::string name, value;
};

Scene parseScene(std::string_view toml, const std::string& source, const ModelDescription& md,
                 const std::vector<ParameterOverride>& overrides = {});
// A scene file is a regular file of at most this size (material maps of a 2000 x 2000 grid fit).
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t{256} << 20;
Scene readScene(const std::filesystem::path& file, const ModelDescription& md,
                const std::vector<ParameterOverride>& overrides = {});

// The structural UInt64 grid parameter `name` (nx or ny) of the model; InputError "<model> has no
// structural UInt64 parameter <name> to <purpose>" when there is none.
const Variable& gridVariable(const ModelDescription& md, const char* name, const std::string& purpose);
// The scene on a grid of nx x ny points: its [parameters] nx and ny replaced (or added). InputError as
// gridVariable.
Scene sceneWithGrid(const Scene& scene, const ModelDescription& md, std::uint64_t nx, std::uint64_t ny,
                    const std::string& purpose);

// Text of a value for messages and HDF5 attributes: enumeration items by name, arrays as [a, b].
std::string describeValues(const Setting& s, const ModelDescription& md);

}  // namespace peristep::host
