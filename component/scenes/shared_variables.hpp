#pragma once
// The variables more than one scene reads: the grid, the material constants, the loads, the fields and the
// specimen's maps and grips (scenes/shared_variables.cpp), with their enumeration types and the units of
// every variable. A scene's own variables are in its declaration (scenes/scene_declaration.hpp).
#include <vector>

#include "core/variable_declaration.hpp"

namespace peristep {

// Value references a scene's own declarations refer to: the structural parameters that size arrays and the
// inputs outputs depend on.
namespace shared_vr {
inline constexpr ValueReference nx = 1, ny = 2, nModes = 3, scene = 10, loadFactor = 30, loadDisplacement = 31;
}  // namespace shared_vr

// Images are [ny][nx]: the outer dimension is ny (FMI arrays are row-major).
inline std::vector<ValueReference> imageDimensions() { return {shared_vr::ny, shared_vr::nx}; }

// The inputs an output depends on (Variable::dependencies): loadFactor, both loads, or none (fixed once the
// scene is built).
inline std::vector<ValueReference> onLoadFactor() { return {shared_vr::loadFactor}; }
inline std::vector<ValueReference> onBothLoads() { return {shared_vr::loadFactor, shared_vr::loadDisplacement}; }
inline std::vector<ValueReference> onNoInput() { return {}; }

const std::vector<Variable>& sharedVariables();
const std::vector<EnumerationType>& sharedEnumerations();
const std::vector<UnitDefinition>& unitDefinitions();
// Value sets of Int32 outputs (xiDistribution): constants of api/peristep.h, not FMI enumeration types.
const std::vector<EnumerationType>& outputEnumerations();

}  // namespace peristep
