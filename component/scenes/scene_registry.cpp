// The scenes of the component, one line each: a scene is its declaration (scenes/scene_declaration.hpp).
#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "scenes/scene_declaration.hpp"

// X(function returning the scene's SceneDeclaration), in the order of the `scene` enumeration.
#define PERISTEP_SCENES(X) \
  X(smoothScene)           \
  X(compositeScene)        \
  X(interfaceCrackScene)   \
  X(glassCeramicScene)     \
  X(plexiglassCrackScene)  \
  X(bendingOneNotchScene)  \
  X(bendingTwoNotchesScene) \
  X(klPlateScene)          \
  X(specimenScene)         \
  X(gamutBarScene)         \
  X(learnedFractureScene)  \
  X(patchTestScene)

namespace peristep {

#define PERISTEP_DECLARE_SCENE(f) SceneDeclaration f();
PERISTEP_SCENES(PERISTEP_DECLARE_SCENE)
#undef PERISTEP_DECLARE_SCENE

const std::vector<SceneDeclaration>& sceneDeclarations() {
#define PERISTEP_LIST_SCENE(f) f(),
  static const std::vector<SceneDeclaration> scenes{PERISTEP_SCENES(PERISTEP_LIST_SCENE)};
#undef PERISTEP_LIST_SCENE
  return scenes;
}

const SceneDeclaration* findScene(SceneId id) {
  const auto& s = sceneDeclarations();
  const auto it = std::find_if(s.begin(), s.end(), [id](const SceneDeclaration& d) { return d.id == id; });
  return it == s.end() ? nullptr : &*it;
}

double ownValue(const SceneParameters& p, ValueReference vr) {
  const auto it = p.own.find(vr);
  if (it != p.own.end() && !it->second.empty()) return it->second.front();
  const SceneDeclaration* scene = findScene(p.scene);
  if (scene)
    for (const Variable& v : scene->variables)
      if (v.vr == vr && !v.start.empty()) return std::stod(std::string(v.start));
  throw InvalidInput("internal error: the scene has no parameter with value reference " + std::to_string(vr));
}

}  // namespace peristep
