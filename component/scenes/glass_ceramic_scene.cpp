// The pre-cracked glass-ceramic plate of 000 Sec. 5: a quasi-static specimen preset (scenes/glass_ceramic.hpp).
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {

namespace {

std::unique_ptr<Runner> fracturePreset(const SceneParameters& p) { return makeSpecimenRunner(withPreset(p)); }

}  // namespace

SceneDeclaration glassCeramicScene() {
  return {.id = SceneId::GlassCeramic,
          .name = "glassCeramic",
          .description =
              "Pre-cracked glass-ceramic plate opened by loadDisplacement; microstructure from seed or its PCA field "
              "(Fan et al., Sec. 5); a preset of the specimen scene (materialField glassCeramic, grips bottom and top, "
              "reactions as the specimen's); quasi-static, any step size: the paper's plate is Lx = 800e-6 m, Ly = 400e-6 m "
              "(e.g. nx = 51, ny = 26), opened in increments of 4e-9 m, one per step",
          .make = fracturePreset};
}

}  // namespace peristep
