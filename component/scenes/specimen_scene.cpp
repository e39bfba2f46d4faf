// The importer's specimen (scenes/specimen.hpp): its model picks the runner.
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {

namespace {

std::unique_ptr<Runner> specimenRunner(const SceneParameters& p) {
  if (isDynamic(p)) return makeDynamicRunner(p);
  return p.specimen.model == SpecimenModel::Elastic ? makeElasticSpecimenRunner(p) : makeSpecimenRunner(p);
}

}  // namespace

SceneDeclaration specimenScene() {
  return {.id = SceneId::Specimen,
          .name = "specimen",
          .description =
              "The importer's specimen: plate Lx x Ly on the vertex grid, material maps materialYoungsModulus, "
              "materialPoissonRatio, materialFractureEnergy, pre-cracks crackX0..crackY1, grips gripLeft..gripTop "
              "moved by loadFactor; specimenModel quasiStatic: brittle fracture (000 Sec. 3.3), every step breaks "
              "bonds until equilibrium at its load; elastic: the same without fracture; dynamic: the state-based model "
              "of 001 over each communication step, the held grips moving at loadFactor * (gripVx, gripVy)",
          .make = specimenRunner};
}

}  // namespace peristep
