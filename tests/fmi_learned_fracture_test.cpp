// Scene learnedFracture through the C ABI: the learned LPS model of 003 predicting the MD fracture samples
// frame by frame gives, bit for bit, the library's run (learning::predictFracture) and errors
// (learning::predictionError) that bench/learn_predict prints; an FMU state continues bit for bit; a
// missing resources directory, a wrong grid, a step that is not whole frames and one past the last frame
// are refused with one message.
#include <catch2/catch.hpp>

#include "fmi_abi_support.hpp"
#include "fmi_refusal.hpp"
#include "learning/md_fracture_samples.hpp"

using namespace peristep::learning;

namespace {

const MdFractureData& data() {
  static const MdFractureData d = readMdFractureData(PERISTEP_RESOURCES_PATH "md_fracture_samples.bin");
  return d;
}

void setUp(Session& s, std::int64_t sample, std::uint64_t n) {
  REQUIRE(s.configure(n, n) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_LEARNED_FRACTURE) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_LEARNED_SAMPLE, sample) == fmi3OK);
}

}  // namespace

TEST_CASE("learnedFracture predicts each MD sample as the library does, bit for bit", "[abi][learned]") {
  const struct {
    std::int64_t value;
    std::size_t index;
  } cases[] = {{PERISTEP_LEARNED_TRAINING, 0}, {PERISTEP_LEARNED_TEST, 1}, {PERISTEP_LEARNED_TRAINING_FINE, 2}};
  for (const auto& c : cases) {
    const FractureFrames& frames = data().samples[c.index];
    // learnedCriticalStretch's start 0 takes the s0 learned with the model.
    const PredictionCase pc = predictionCase(frames.grid, kMdFractureSamples[c.index], data().model, data().model.s0, 8);
    const FractureRun run = predictFracture(pc.op, frames, pc.setup);
    REQUIRE(run.finite);
    const PredictionError expected = predictionError(pc.op, frames, run, pc.setup);
    INFO("sample " << kMdFractureSamples[c.index].name);

    Session s;
    const std::size_t n = frames.grid.nx, points = n * n;
    setUp(s, c.value, n);
    const double interval = data().intervalSeconds[c.index];
    REQUIRE(s.initialize(0, 40 * interval) == fmi3OK);
    CHECK(s.getFloat64(PERISTEP_VR_PREDICTION_ERROR_U).at(0) == 0.0);  // no frame predicted yet
    for (int f = 0; f < 40; ++f) REQUIRE(s.step(f * interval, interval) == fmi3OK);
    CHECK(s.getFloat64(PERISTEP_VR_PREDICTION_ERROR_U).at(0) == expected.displacement);
    CHECK(s.getFloat64(PERISTEP_VR_PREDICTION_ERROR_DAMAGE).at(0) == expected.damage);
    const std::vector<double> ux = s.getFloat64(PERISTEP_VR_UX, points), damage = s.getFloat64(PERISTEP_VR_DAMAGE, points);
    const std::vector<double> truth = pc.op.damage(run.maxStretch.back(), pc.setup.s0);
    for (std::size_t p = 0; p < points; ++p) {
      REQUIRE(ux[p] == run.u.back()[2 * p] * 1e-10);  // A -> m
      REQUIRE(damage[p] == truth[p]);
    }
  }
}

TEST_CASE("learnedFracture: sample III gives bench/learn_predict's errors, and a state continues bit for bit",
          "[abi][learned]") {
  Session s;
  setUp(s, PERISTEP_LEARNED_TRAINING, 20);
  const double interval = data().intervalSeconds[0];
  REQUIRE(s.initialize(0, 40 * interval) == fmi3OK);
  REQUIRE(s.step(0, 20 * interval) == fmi3OK);  // 20 frames in one communication step
  fmi3FMUState state = nullptr;
  REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
  std::vector<double> first;
  for (int k = 0; k < 2; ++k) {
    if (k == 1) REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
    for (int f = 20; f < 40; f += 5) REQUIRE(s.step(f * interval, 5 * interval) == fmi3OK);
    const std::vector<double> uy = s.getFloat64(PERISTEP_VR_UY, 400);
    if (k == 0) first = uy;
    else CHECK(uy == first);
  }
  REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
  // docs/verification.md, 003: III training, h = 5 A, the learned s0 = 0.3028: e_u 14.5%, e_phi 36.1%
  // (003: 27 / 9).
  CHECK(data().model.s0 == Approx(0.3028).epsilon(1e-3));
  CHECK(s.getFloat64(PERISTEP_VR_PREDICTION_ERROR_U).at(0) == Approx(0.145).epsilon(3e-3));
  CHECK(s.getFloat64(PERISTEP_VR_PREDICTION_ERROR_DAMAGE).at(0) == Approx(0.361).epsilon(3e-3));
}

TEST_CASE("learnedFracture with 003's s0 = 0.11 gives bench/learn_predict --s0 0.11's errors", "[abi][learned]") {
  Session s;
  setUp(s, PERISTEP_LEARNED_TRAINING, 20);
  REQUIRE(s.setFloat64(PERISTEP_VR_LEARNED_CRITICAL_STRETCH, {0.11}) == fmi3OK);
  const double interval = data().intervalSeconds[0];
  REQUIRE(s.initialize(0, 40 * interval) == fmi3OK);
  REQUIRE(s.step(0, 40 * interval) == fmi3OK);
  // docs/verification.md, 003: e_u 49.1%, e_phi 53.2%.
  CHECK(s.getFloat64(PERISTEP_VR_PREDICTION_ERROR_U).at(0) == Approx(0.4910).epsilon(1e-3));
  CHECK(s.getFloat64(PERISTEP_VR_PREDICTION_ERROR_DAMAGE).at(0) == Approx(0.5316).epsilon(1e-3));
}

TEST_CASE("learnedFracture refuses what it cannot run, with one message", "[abi][learned]") {
  const double interval = data().intervalSeconds[0];
  SECTION("no resources") {
    Session s(true, nullptr);
    setUp(s, PERISTEP_LEARNED_TRAINING, 20);
    requireRefused(s, "fmi3ExitInitializationMode", "no resourcePath", [&] { return s.initialize(0, 1); });
  }
  SECTION("a grid other than the sample's") {
    Session s;
    setUp(s, PERISTEP_LEARNED_TRAINING_FINE, 20);
    requireRefused(s, "fmi3ExitInitializationMode", "set nx = 31, ny = 31", [&] { return s.initialize(0, 1); });
  }
  SECTION("a step that is not whole frames") {
    Session s;
    setUp(s, PERISTEP_LEARNED_TEST, 20);
    REQUIRE(s.initialize(0, 100 * interval) == fmi3OK);
    requireRefused(s, "fmi3DoStep", "whole MD frame intervals", [&] { return s.step(0, 0.5 * interval); });
  }
  SECTION("a step past frame 40") {
    Session s;
    setUp(s, PERISTEP_LEARNED_TEST, 20);
    REQUIRE(s.initialize(0, 100 * interval) == fmi3OK);
    requireRefused(s, "fmi3DoStep", "goes beyond them", [&] { return s.step(0, 41 * interval); });
  }
}
