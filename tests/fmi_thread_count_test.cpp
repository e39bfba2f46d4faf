// Every built-in scene (its coarse set-up of fmi_scene_setups.hpp) gives the same bits on one OpenMP
// thread and on two: set-up, two steps, every Float64 output. So a sample computed under mpirun (one
// thread per rank) equals the serial run's, and statistics of outputs that do not depend on xi have a
// standard deviation of exactly 0.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cstring>

#include "fmi_abi_support.hpp"
#include "fmi_float64_variables.hpp"
#include "fmi_scene_setups.hpp"
#include "model_description_xml.hpp"

namespace {

std::vector<double> twoSteps(std::int64_t scene, double h, int threads) {
  omp_set_num_threads(threads);
  static const std::vector<Float64Variable> all = float64Variables();
  Session s;
  setUpCoarseScene(s, scene);
  REQUIRE(s.initialize(0, 10) == fmi3OK);
  std::vector<double> outputs;
  for (int k = 0; k < 2; ++k) {
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.5 * (k + 1)}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_DISPLACEMENT, {0.07e-6 * (k + 1)}) == fmi3OK);
    REQUIRE(s.step(k * h, h) == fmi3OK);
    for (const Float64Variable& v : all) {
      if (v.causality != "output") continue;
      const std::vector<double> values = s.getFloat64(v.vr, elements(s, v));
      REQUIRE(values.size() == elements(s, v));
      outputs.insert(outputs.end(), values.begin(), values.end());
    }
  }
  return outputs;
}

}  // namespace

TEST_CASE("every scene: one thread and two give the same bits", "[abi][threads][scenes]") {
  const XmlDocument doc(PERISTEP_GENERATED_MODEL_DESCRIPTION);
  xmlNodePtr scenes = nullptr;
  for (xmlNodePtr t : children(firstChild(doc.root(), "TypeDefinitions")))
    if (attribute(t, "name") == "PeriStep.Scene") scenes = t;
  REQUIRE(scenes != nullptr);
  const int threads = omp_get_max_threads();
  std::size_t tested = 0;
  for (xmlNodePtr item : children(scenes, "Item")) {
    const std::string name = attribute(item, "name");
    INFO(name);
    const std::int64_t scene = std::stoll(attribute(item, "value"));
    const double h = coarseStep(scene, attribute(item, "description"));
    const std::vector<double> one = twoSteps(scene, h, 1), two = twoSteps(scene, h, 2);
    REQUIRE(one.size() == two.size());
    std::size_t differ = 0, first = one.size();
    for (std::size_t i = 0; i < one.size(); ++i)
      if (std::memcmp(&one[i], &two[i], sizeof(double)) != 0 && differ++ == 0) first = i;
    INFO(differ << " of " << one.size() << " output values differ, the first at " << first);
    CHECK(differ == 0);
    ++tested;
  }
  omp_set_num_threads(threads);
  CHECK(tested == 11);
}
