#pragma once
// An FMU ready for the commands: unpacked, its model description read and checked to offer
// Co-Simulation. The binary itself is loaded by whoever instantiates it.
#include <filesystem>
#include <string>
#include <vector>

#include "../fmu_archive.hpp"
#include "../model_description.hpp"
#include "../scene_file.hpp"

namespace peristep::host {

struct OpenedFmu {
  explicit OpenedFmu(const std::filesystem::path& fmu);

  FmuArchive archive;
  ModelDescription md;
};

// The scene file at `path`, or the built-in default scene when `path` is empty, with the command
// line's `--set name=value` texts applied to its [parameters].
Scene loadScene(const std::string& path, const ModelDescription& md, const std::vector<std::string>& set = {});

}  // namespace peristep::host
