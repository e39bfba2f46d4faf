// Every built-in scene (the PeriStep.Scene items of the generated modelDescription.xml, each on its coarse
// set-up of fmi_scene_setups.hpp): an FMU state taken after two steps, restored in the same instance and,
// serialized, in a fresh one, repeats the next two steps bit for bit. The loads grow from step to step:
// after the state, the glass-ceramic plate breaks its first bonds beyond the pre-crack (4 at 0.14 um) and
// the 002 bar its first elements; kept below the plate's crack run, which costs minutes on a loaded machine.
#include <catch2/catch.hpp>

#include "fmi_abi_support.hpp"
#include "fmi_scene_setups.hpp"
#include "model_description_xml.hpp"

namespace {

// Outputs that hold the run's state; forceEvaluations counts work across fmi3SetFMUState (documented).
const fmi3ValueReference kScalars[] = {
    PERISTEP_VR_TIME,          PERISTEP_VR_REACTION_FORCE,   PERISTEP_VR_CRACK_LENGTH,
    PERISTEP_VR_BROKEN_BONDS,  PERISTEP_VR_STRAIN_ENERGY,    PERISTEP_VR_FRACTURE_ENERGY,
    PERISTEP_VR_TOUGHNESS_KIC, PERISTEP_VR_ERROR_L2,         PERISTEP_VR_KINETIC_ENERGY,
    PERISTEP_VR_EXTERNAL_WORK, PERISTEP_VR_REACTION_TOP_Y,   PERISTEP_VR_BAR_STRESS,
    PERISTEP_VR_BAR_STRAIN,    PERISTEP_VR_CYCLIC_EXPONENT,  PERISTEP_VR_CYCLIC_COEFFICIENT};
const fmi3ValueReference kImages[] = {PERISTEP_VR_UX, PERISTEP_VR_UY, PERISTEP_VR_DAMAGE};

// Steps `first` .. first + count - 1 of size h at loadFactor 0.25 (k + 1) and loadDisplacement 0.035 (k + 1) um;
// the outputs above after each.
std::vector<std::vector<double>> steps(Session& s, int first, int count, double h) {
  const fmi3ValueReference nxy[] = {PERISTEP_VR_NX, PERISTEP_VR_NY};
  fmi3UInt64 size[2] = {};
  REQUIRE(s.fmu.fmi3GetUInt64(s.instance, nxy, 2, size, 2) == fmi3OK);
  std::vector<std::vector<double>> rows;
  for (int k = first; k < first + count; ++k) {
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.25 * (k + 1)}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_DISPLACEMENT, {0.035e-6 * (k + 1)}) == fmi3OK);
    REQUIRE(s.step(k * h, h) == fmi3OK);
    std::vector<double> row;
    for (fmi3ValueReference vr : kScalars) row.push_back(s.getFloat64(vr).at(0));
    for (fmi3ValueReference vr : kImages) {
      const std::vector<double> field = s.getFloat64(vr, size[0] * size[1]);
      REQUIRE(!field.empty());
      row.insert(row.end(), field.begin(), field.end());
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

TEST_CASE("every scene: a restored FMU state repeats the following steps bit for bit", "[abi][fmustate][scenes]") {
  const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  xmlNodePtr scenes = nullptr;
  for (xmlNodePtr t : children(firstChild(doc.root(), "TypeDefinitions")))
    if (attribute(t, "name") == "PeriStep.Scene") scenes = t;
  REQUIRE(scenes != nullptr);
  std::size_t tested = 0;
  for (xmlNodePtr item : children(scenes, "Item")) {
    const std::string name = attribute(item, "name");
    INFO(name);
    const std::int64_t scene = std::stoll(attribute(item, "value"));
    const double h = coarseStep(scene, attribute(item, "description"));
    Session s;
    setUpCoarseScene(s, scene);
    REQUIRE(s.initialize(0, 10) == fmi3OK);
    steps(s, 0, 2, h);
    fmi3FMUState state = nullptr;
    REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
    const auto reference = steps(s, 2, 2, h);

    REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    CHECK(steps(s, 2, 2, h) == reference);

    const std::vector<fmi3Byte> bytes = s.serialize(state);
    REQUIRE(!bytes.empty());
    Session fresh;
    fmi3FMUState copy = nullptr;
    REQUIRE(fresh.fmu.fmi3DeserializeFMUState(fresh.instance, bytes.data(), bytes.size(), &copy) == fmi3OK);
    REQUIRE(fresh.fmu.fmi3SetFMUState(fresh.instance, copy) == fmi3OK);
    CHECK(steps(fresh, 2, 2, h) == reference);
    REQUIRE(fresh.fmu.fmi3FreeFMUState(fresh.instance, &copy) == fmi3OK);
    REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
    CHECK(s.log.errors() == 0);
    CHECK(fresh.log.errors() == 0);
    ++tested;
  }
  CHECK(tested == 11);
}
