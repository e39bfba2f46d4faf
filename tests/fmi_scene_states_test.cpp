// Every built-in scene (the PeriStep.Scene items of the generated modelDescription.xml, each on its coarse
// set-up of fmi_scene_setups.hpp): an FMU state taken after two steps, restored in the same instance and,
// serialized, in a fresh one, repeats the next two steps bit for bit in every output, counters included.
// The loads grow from step to step:
// after the state, the glass-ceramic plate breaks its first bonds beyond the pre-crack (4 at 0.14 um) and
// the 002 bar its first elements; kept below the plate's crack run, which costs minutes on a loaded machine.
#include <catch2/catch.hpp>

#include "fmi_abi_support.hpp"
#include "fmi_float64_variables.hpp"
#include "fmi_scene_setups.hpp"
#include "model_description_xml.hpp"

namespace {

// Steps `first` .. first + count - 1 of size h at loadFactor 0.25 (k + 1) and loadDisplacement 0.035 (k + 1) um;
// after each, every Float64 output of the model description (fields whole), the time and the counters.
std::vector<std::vector<double>> steps(Session& s, int first, int count, double h) {
  static const std::vector<Float64Variable> all = float64Variables();
  std::vector<std::vector<double>> rows;
  for (int k = first; k < first + count; ++k) {
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.25 * (k + 1)}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_DISPLACEMENT, {0.035e-6 * (k + 1)}) == fmi3OK);
    REQUIRE(s.step(k * h, h) == fmi3OK);
    std::vector<double> row = s.getFloat64(PERISTEP_VR_TIME);
    for (const Float64Variable& v : all) {
      if (v.causality != "output") continue;
      const std::vector<double> values = s.getFloat64(v.vr, elements(s, v));
      INFO(v.name);
      REQUIRE(values.size() == elements(s, v));
      row.insert(row.end(), values.begin(), values.end());
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

TEST_CASE("every scene: a restored FMU state repeats the following steps bit for bit", "[abi][fmustate][scenes]") {
  std::size_t tested = 0;
  for (const SceneItem& item : sceneItems()) {
    INFO(item.name);
    const std::int64_t scene = item.value;
    const double h = coarseStep(scene, item.description);
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
  CHECK(tested >= 11);  // the eleven scenes of the papers and any added since
}
