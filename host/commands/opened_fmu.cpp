#include "opened_fmu.hpp"

#include "../default_scene.hpp"
#include "../host_errors.hpp"
#include "../scene_overrides.hpp"

namespace peristep::host {

OpenedFmu::OpenedFmu(const std::filesystem::path& fmu)
    : archive(fmu), md(readModelDescription(archive.modelDescriptionFile())) {
  if (md.coSimulationIdentifier.empty())
    throw InputError(fmu.string() + ": the FMU offers no Co-Simulation interface, which the host needs");
}

Scene loadScene(const std::string& path, const ModelDescription& md, const std::vector<std::string>& set) {
  std::vector<ParameterOverride> overrides;
  for (const std::string& text : set) overrides.push_back(parseOverride(text));
  if (path.empty()) return parseScene(defaultSceneText(), "<built-in default scene>", md, overrides);
  return readScene(path, md, overrides);
}

}  // namespace peristep::host
