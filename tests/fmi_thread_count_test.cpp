// Every built-in scene (its coarse set-up of fmi_scene_setups.hpp) gives the same bits on one OpenMP
// thread and on two: set-up, two steps, every Float64 output. So a sample computed under mpirun (one
// thread per rank) equals the serial run's, and statistics of outputs that do not depend on xi have a
// standard deviation of exactly 0.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>

#include "fmi_abi_support.hpp"
#include "fmi_float64_variables.hpp"
#include "fmi_scene_setups.hpp"
#include "model_description_xml.hpp"

namespace {

// OpenBLAS on one thread, as `peristep sample` runs it (its own results change with its thread count), set
// before this test process loads the FMU.
[[maybe_unused]] const bool serialBlas = (setenv("OPENBLAS_NUM_THREADS", "1", 1), true);

// Two steps of `scene` after `setUp`, on `threads` OpenMP threads: every Float64 output after each.
template <class SetUp>
std::vector<double> twoSteps(SetUp setUp, double h, int threads) {
  omp_set_num_threads(threads);
  static const std::vector<Float64Variable> all = float64Variables();
  Session s;
  setUp(s);
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
  const int threads = omp_get_max_threads();
  std::size_t tested = 0;
  for (const SceneItem& item : sceneItems()) {
    INFO(item.name);
    const std::int64_t scene = item.value;
    const double h = coarseStep(scene, item.description);
    const auto setUp = [&](Session& s) { setUpCoarseScene(s, scene); };
    const std::vector<double> one = twoSteps(setUp, h, 1), two = twoSteps(setUp, h, 2);
    REQUIRE(one.size() == two.size());
    std::size_t differ = 0, first = one.size();
    for (std::size_t i = 0; i < one.size(); ++i)
      if (std::memcmp(&one[i], &two[i], sizeof(double)) != 0 && differ++ == 0) first = i;
    INFO(differ << " of " << one.size() << " output values differ, the first at " << first);
    CHECK(differ == 0);
    ++tested;
  }
  omp_set_num_threads(threads);
  CHECK(tested >= 11);  // the eleven scenes of the papers and any added since
}

// Grids large enough for several blocks of the fixed-block sums (2 x 65 x 65 unknowns) and for the KL
// field's dense eigensolver (33 x 33 points).
TEST_CASE("Test 1 at 65 x 65 and the KL plate at 33 x 33: one thread and two give the same bits", "[abi][threads]") {
  const int threads = omp_get_max_threads();
  const auto check = [](auto setUp) {
    const std::vector<double> one = twoSteps(setUp, 0.25, 1), two = twoSteps(setUp, 0.25, 2);
    REQUIRE(one.size() == two.size());
    CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)) == 0);
  };
  check([](Session& s) {
    REQUIRE(s.configure(65, 65, 1) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_SMOOTH) == fmi3OK);
  });
  check([](Session& s) {
    REQUIRE(s.configure(33, 33, 4) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_KL_PLATE) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_XI, {1.0, -0.5, 0.25, 0.0}) == fmi3OK);
  });
  omp_set_num_threads(threads);
}
