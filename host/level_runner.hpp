#pragma once
// One level of a refinement study, run in a forked child process: each level's peak memory is then
// its own (wait4 reports the child's maximum resident set), and a level that crashes or runs out of
// memory is reported instead of ending the study.
#include <cstdint>

#include "convergence_table.hpp"
#include "fmu_archive.hpp"
#include "fmu_instance.hpp"
#include "scene_file.hpp"

namespace peristep::host {

// The scene with nx = ny = level + 1 (its [parameters] nx and ny, if any, are replaced).
Scene sceneAtLevel(const Scene& scene, const ModelDescription& md, std::uint64_t level);

// Runs every load increment of the scene at this level and fills a row (rate left for computeRates).
// The parent must not have loaded the FMU binary: the child does, so nothing of the component is
// shared across levels. Throws RunError with the child's message when the level fails.
LevelResult runLevel(const FmuArchive& fmu, const ModelDescription& md, const Scene& scene, std::uint64_t level,
                     const FmuInstance::Options& options);

}  // namespace peristep::host
