// The dynamic scenes of 001 Sec. 6: presets of the specimen with the state-based model (scenes/dynamic_scene.hpp).
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {

namespace {

std::unique_ptr<Runner> dynamicPreset(const SceneParameters& p) { return makeDynamicRunner(withPreset(p)); }

}  // namespace

SceneDeclaration plexiglassCrackScene() {
  return {.id = SceneId::PlexiglassCrack,
          .name = "plexiglassCrack",
          .description =
              "Dynamic crack in a pre-cracked Plexiglass square, bottom strips pulled apart (Jha-Lipton, Sec. 6.1); "
              "communication step 2e-6 s, stop time 34e-6 s (500 internal steps of 0.004 us per step)",
          .make = dynamicPreset};
}

SceneDeclaration bendingOneNotchScene() {
  return {.id = SceneId::BendingOneNotch,
          .name = "bendingOneNotch",
          .description =
              "Dynamic three-point bending of a beam with one pre-crack (Jha-Lipton, Sec. 6.2); communication step "
              "1e-5 s, stop time 3.5e-4 s (about 2857 internal steps of 0.0035 us per step)",
          .make = dynamicPreset};
}

SceneDeclaration bendingTwoNotchesScene() {
  return {.id = SceneId::BendingTwoNotches,
          .name = "bendingTwoNotches",
          .description =
              "Dynamic three-point bending of a beam with two pre-cracks (Jha-Lipton, Sec. 6.2); communication step "
              "1e-5 s, stop time 3.5e-4 s (about 2857 internal steps of 0.0035 us per step)",
          .make = dynamicPreset};
}

}  // namespace peristep
