// The manufactured-solution scenes of 000 Sec. 4 (Tests 1-3): elastic specimens with an exact solution.
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {

namespace {

std::unique_ptr<Runner> elasticPreset(const SceneParameters& p) { return makeElasticSpecimenRunner(withPreset(p)); }

}  // namespace

SceneDeclaration smoothScene() {
  return {.id = SceneId::Smooth,
          .name = "smooth",
          .description =
              "Smooth manufactured solution, one random coordinate (Fan et al., Test 1): the specimen with specimenModel "
              "elastic, every side held, exactSolution smooth; quasi-static: the DefaultExperiment fits",
          .make = elasticPreset};
}

SceneDeclaration compositeScene() {
  return {.id = SceneId::Composite,
          .name = "composite",
          .description =
              "Bimaterial composite, two random coordinates (Fan et al., Test 2): the specimen with specimenModel "
              "elastic, every side held, exactSolution composite; quasi-static: the DefaultExperiment fits",
          .make = elasticPreset};
}

SceneDeclaration interfaceCrackScene() {
  return {.id = SceneId::InterfaceCrack,
          .name = "interfaceCrack",
          .description =
              "Crack on a bimaterial interface, two random coordinates (Fan et al., Test 3): the specimen with "
              "specimenModel elastic, every side held, exactSolution interfaceCrack and the crack from 2 delta beyond the "
              "left edge to the origin; quasi-static: the DefaultExperiment fits",
          .make = elasticPreset};
}

}  // namespace peristep
