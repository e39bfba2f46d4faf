// The step size each dynamic scene documents in its description (the PeriStep.Scene enumeration of
// modelDescription.xml, also shown in the FMU's documentation/index.html) is what an fmi3DoStep of that
// size costs: "communication step H s, stop time T s (N internal steps of D us per step)" holds when a
// step of H at internalTimeStep = 0 spends N force evaluations (central difference: one per internal step).
#include <catch2/catch.hpp>
#include <cmath>
#include <regex>

#include "fmi_abi_support.hpp"
#include "fmi_scene_setups.hpp"
#include "model_description_xml.hpp"

TEST_CASE("each dynamic scene documents a communication step that its internal step divides as stated",
          "[modelDescription][dynamics]") {
  const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  xmlNodePtr scenes = nullptr;
  for (xmlNodePtr t : children(firstChild(doc.root(), "TypeDefinitions")))
    if (attribute(t, "name") == "PeriStep.Scene") scenes = t;
  REQUIRE(scenes != nullptr);
  const std::regex documented(
      R"(communication step ([0-9.e+-]+) s, stop time ([0-9.e+-]+) s )"
      R"(\((about )?([0-9]+) internal steps of ([0-9.]+) us per step\))");
  std::size_t dynamicScenes = 0;
  for (xmlNodePtr item : children(scenes, "Item")) {
    const std::string name = attribute(item, "name"), description = attribute(item, "description");
    INFO(name << ": " << description);
    std::smatch m;
    const bool dynamic = description.rfind("Dynamic", 0) == 0;
    CHECK(std::regex_search(description, m, documented) == dynamic);  // every dynamic scene states its step
    if (!dynamic || m.empty()) continue;
    ++dynamicScenes;
    const double step = std::stod(m[1]), stop = std::stod(m[2]), internal = std::stod(m[5]) * 1e-6;
    const long stated = std::stol(m[4]);
    const double perStep = step / internal;
    CHECK(std::abs(perStep - stated) <= (m[3].matched ? 1.0 : 1e-9 * perStep));  // "about": within one step
    const double steps = stop / step;
    CHECK(std::abs(steps - std::round(steps)) <= 1e-9 * steps);  // the stop time is a whole number of steps

    // One communication step of the documented size: the central difference takes ceil(H / D) internal
    // steps, one force evaluation each.
    Session s;
    setUpCoarseScene(s, std::stoll(attribute(item, "value")));
    REQUIRE(s.initialize(0, stop) == fmi3OK);
    const double before = s.getFloat64(PERISTEP_VR_FORCE_EVALUATIONS).at(0);
    REQUIRE(s.step(0, step) == fmi3OK);
    const double spent = s.getFloat64(PERISTEP_VR_FORCE_EVALUATIONS).at(0) - before;
    CHECK(spent == std::ceil(perStep - 1e-6));
    CHECK(s.log.errors() == 0);
  }
  CHECK(dynamicScenes == 3);
}
