// Every Float64 parameter and input of the model description, in every built-in scene (its coarse set-up
// of fmi_scene_setups.hpp), set to 1e308, -1e308, 1e-300 and a subnormal number (every element of an
// array): the component either refuses it (in the set call, in initialization or in the step) with a
// message, or initializes and steps with every Float64 output finite. Never fmi3OK with a non-finite
// output, never a refusal without a message.
#include <catch2/catch.hpp>
#include <string>

#include "fmi_abi_support.hpp"
#include "fmi_float64_variables.hpp"
#include "fmi_scene_setups.hpp"

namespace {

constexpr double kExtremes[] = {1e308, -1e308, 1e-300, 4.9e-320};

struct Outcome {
  std::size_t refused = 0, finite = 0;
};

// A refusal carries a logged error message; returns whether the call was refused.
bool refused(fmi3Status status, const Session& s) {
  if (status == fmi3OK) return false;
  CHECK(status == fmi3Error);
  REQUIRE(s.log.errors() >= 1);
  CHECK(s.log.records.back().message.size() > 10);
  return true;
}

void sweepScene(std::int64_t scene, const std::string& description) {
  const std::vector<Float64Variable> all = float64Variables();
  const double h = coarseStep(scene, description);
  Outcome outcome;
  for (const Float64Variable& v : all) {
    if (v.causality != "parameter" && v.causality != "input") continue;
    for (double value : kExtremes) {
      INFO(v.name << " = " << value);
      Session s;
      setUpCoarseScene(s, scene);
      const std::vector<double> values(elements(s, v), value);
      if (refused(s.fmu.fmi3SetFloat64(s.instance, &v.vr, 1, values.data(), values.size()), s) ||
          refused(s.initialize(0, 10), s) || refused(s.step(0, h), s)) {
        ++outcome.refused;
        continue;
      }
      for (const Float64Variable& out : all) {
        if (out.causality != "output") continue;
        INFO(out.name);
        const std::vector<double> got = s.getFloat64(out.vr, elements(s, out));
        REQUIRE(!got.empty());
        for (double x : got) REQUIRE(std::isfinite(x));
      }
      CHECK(s.log.errors() == 0);
      ++outcome.finite;
    }
  }
  // Both kinds occur in every scene: the sweep reaches the set-up and the step, not only the set calls.
  CHECK(outcome.refused > 0);
  CHECK(outcome.finite > 0);
}

}  // namespace

#define PERISTEP_EXTREME_VALUES_TEST(scene, description)                                                   \
  TEST_CASE("extreme parameter and input values: " #scene " refuses them or stays finite", "[abi][extreme]") { \
    sweepScene(scene, description);                                                                         \
  }

PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_SMOOTH, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_COMPOSITE, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_INTERFACE_CRACK, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_KL_PLATE, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_SPECIMEN, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_GLASS_CERAMIC, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_GAMUT_BAR, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_LEARNED_FRACTURE, "")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_PLEXIGLASS_CRACK, "Dynamic")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_BENDING_ONE_NOTCH, "Dynamic")
PERISTEP_EXTREME_VALUES_TEST(PERISTEP_SCENE_BENDING_TWO_NOTCHES, "Dynamic")
