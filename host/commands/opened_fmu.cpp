#include "opened_fmu.hpp"

#include "../default_scene.hpp"
#include "../host_errors.hpp"

namespace peristep::host {

OpenedFmu::OpenedFmu(const std::filesystem::path& fmu)
    : archive(fmu), md(readModelDescription(archive.modelDescriptionFile())) {
  if (md.coSimulationIdentifier.empty())
    throw InputError(fmu.string() + ": the FMU offers no Co-Simulation interface, which the host needs");
}

Scene loadScene(const std::string& path, const ModelDescription& md) {
  if (path.empty()) return parseScene(defaultSceneText(), "<built-in default scene>", md);
  return readScene(path, md);
}

}  // namespace peristep::host
