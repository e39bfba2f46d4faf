#pragma once
// The Float64 variables of the generated modelDescription.xml with their causality and <Dimension>s, their
// element counts in a configured instance, and the built-in scenes: for tests that must cover every
// output, every parameter or every scene, not a chosen list.
#include <string>
#include <vector>

#include "fmi_abi_support.hpp"
#include "model_description_xml.hpp"

struct Float64Variable {
  std::string name, causality;
  fmi3ValueReference vr = 0;
  std::vector<fmi3ValueReference> dimensions;  // structural parameters sizing the array
  std::size_t fixedElements = 1;                // product of the <Dimension start="..."> entries
};

inline std::vector<Float64Variable> float64Variables() {
  const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  std::vector<Float64Variable> out;
  for (xmlNodePtr v : children(firstChild(doc.root(), "ModelVariables"), "Float64")) {
    Float64Variable f{attribute(v, "name"), attribute(v, "causality", "local"),
                      static_cast<fmi3ValueReference>(std::stoul(attribute(v, "valueReference"))), {}, 1};
    for (xmlNodePtr d : children(v, "Dimension")) {
      if (const auto ref = optionalAttribute(d, "valueReference"))
        f.dimensions.push_back(static_cast<fmi3ValueReference>(std::stoul(*ref)));
      else
        f.fixedElements *= std::stoul(attribute(d, "start"));
    }
    out.push_back(std::move(f));
  }
  return out;
}

// The variable's element count in this instance (its dimensions' current values).
inline std::size_t elements(Session& s, const Float64Variable& v) {
  std::size_t n = v.fixedElements;
  for (fmi3ValueReference d : v.dimensions) {
    fmi3UInt64 size = 0;
    REQUIRE(s.fmu.fmi3GetUInt64(s.instance, &d, 1, &size, 1) == fmi3OK);
    n *= static_cast<std::size_t>(size);
  }
  return n;
}

// The items of PeriStep.Scene: every built-in scene.
struct SceneItem {
  std::string name, description;
  std::int64_t value = 0;
};

inline std::vector<SceneItem> sceneItems() {
  const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  std::vector<SceneItem> out;
  for (xmlNodePtr t : children(firstChild(doc.root(), "TypeDefinitions")))
    if (attribute(t, "name") == "PeriStep.Scene")
      for (xmlNodePtr item : children(t, "Item"))
        out.push_back({attribute(item, "name"), attribute(item, "description"), std::stoll(attribute(item, "value"))});
  REQUIRE(!out.empty());
  return out;
}
