// The plate with a Karhunen-Loeve random Young's modulus (000 Sec. 2.2): an elastic specimen preset.
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {

namespace {

std::unique_ptr<Runner> elasticPreset(const SceneParameters& p) { return makeElasticSpecimenRunner(withPreset(p)); }

}  // namespace

SceneDeclaration klPlateScene() {
  return {.id = SceneId::KlPlate,
          .name = "klPlate",
          .description =
              "Plate with a Karhunen-Loeve random Young's modulus (nModes coordinates), stretched by loadFactor: the "
              "specimen with specimenModel elastic, materialField klField, E = 1, every side held, collarDuyDy = 0.01; "
              "quasi-static: the DefaultExperiment fits",
          .make = elasticPreset};
}

}  // namespace peristep
