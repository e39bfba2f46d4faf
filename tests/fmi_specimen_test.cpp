// The specimen scene through the C ABI only: a plate with an inclined edge notch and a stiff circular
// inclusion, pulled at the top, cracks from the notch and passes the inclusion on one side, where the
// same plate without the inclusion cracks straight through its place; an FMU state repeats a cracking
// step, the modulus map carries the KL field, and a bad description is refused with one message.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "fmi_abi_support.hpp"
#include "fmi_refusal.hpp"
#include "fmi_notched_plate.hpp"

using namespace notched_plate;

namespace {

void configure(Session& s, std::uint64_t nx, std::uint64_t ny) {
  REQUIRE(s.configureStructural({PERISTEP_VR_NX, PERISTEP_VR_NY, PERISTEP_VR_NCRACKS}, {nx, ny, 1}) == fmi3OK);
}

// Grips by their start values but the top's displacement.
void setUpNotchedPlate(Session& s, bool inclusion) {
  configure(s, kNx, kNy);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_SPECIMEN) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {kLx}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {kLy}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, youngsModulus(inclusion)) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_MATERIAL_FRACTURE_ENERGY, fractureEnergy(inclusion)) == fmi3OK);
  setNotch(s);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_TOP_UY, {kTopPull}) == fmi3OK);
}

struct Pulled {
  std::vector<double> damage;
  double peakReaction = 0, lastReaction = 0;
};

// Pulls the top up to loadFactor 3.5 (below the first break: the grips must balance there), then in steps
// of 0.25 from 5 until the crack has passed the inclusion by two horizons.
Pulled pull(Session& s) {
  REQUIRE(s.initialize(0, 40) == fmi3OK);
  Pulled r;
  int step = 0;
  for (int k = 14; k <= 40; k = k == 14 ? 20 : k + 1) {
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.25 * k}) == fmi3OK);
    REQUIRE(s.step(step, 1) == fmi3OK);
    ++step;
    r.damage = s.getFloat64(PERISTEP_VR_DAMAGE, kPoints);
    r.lastReaction = s.getFloat64(PERISTEP_VR_REACTION_TOP_Y).at(0);
    if (k == 14) {
      CHECK(r.lastReaction > 0);
      // The held sides balance each other (to 0.3% here: the nonlocal forces with the quadrature weights
      // of 000:(3.18) are not exactly pairwise equal and opposite).
      CHECK(s.getFloat64(PERISTEP_VR_REACTION_BOTTOM_Y).at(0) == Approx(-r.lastReaction).epsilon(0.01));
      CHECK(s.getFloat64(PERISTEP_VR_REACTION_LEFT_Y).at(0) == 0.0);  // free
    }
    r.peakReaction = std::max(r.peakReaction, r.lastReaction);
    if (crackFront(r.damage) >= kPassed) break;
  }
  return r;
}

}  // namespace

TEST_CASE("a notched plate with a stiff inclusion cracks from the notch and passes the inclusion", "[abi][specimen]") {
  Session with, without;
  setUpNotchedPlate(with, true);
  setUpNotchedPlate(without, false);
  const Pulled a = pull(with), b = pull(without);
  for (const Pulled* r : {&a, &b}) {
    CHECK(crackFront(r->damage) >= kPassed);  // grown from the notch tip at x = -0.6
    CHECK(r->lastReaction < 0.5 * r->peakReaction);  // the cracked plate carries less
  }
  CHECK(crackedInInclusion(a.damage) == 0);  // deflected around the inclusion
  CHECK(crackedInInclusion(b.damage) > 5);   // where the plain plate cracks straight through
  // Where it passes the inclusion's centre line x = 0, the crack runs outside the inclusion.
  for (std::size_t j = 0; j < kNy; ++j) {
    const std::size_t i = j * kNx + kNx / 2;
    if (a.damage[i] > kCracked) CHECK(std::abs(yOf(i) - kYc) > kR);
  }
}

TEST_CASE("an FMU state of a cracking specimen repeats its steps bit for bit", "[abi][specimen][state]") {
  Session s;
  setUpNotchedPlate(s, true);
  REQUIRE(s.initialize(0, 10) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {3.5}) == fmi3OK);
  REQUIRE(s.step(0, 1) == fmi3OK);
  fmi3FMUState state = nullptr;
  REQUIRE(s.fmu.fmi3GetFMUState(s.instance, &state) == fmi3OK);
  // Loads 5 and 5.25 grow the crack from the notch tip (bonds break in both steps).
  const auto run = [&] {
    std::vector<double> out;
    for (int k = 0; k < 2; ++k) {
      REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {5.0 + 0.25 * k}) == fmi3OK);
      REQUIRE(s.step(1 + k, 1) == fmi3OK);
      const auto d = s.getFloat64(PERISTEP_VR_DAMAGE, kPoints);
      out.insert(out.end(), d.begin(), d.end());
      out.push_back(s.getFloat64(PERISTEP_VR_REACTION_TOP_Y).at(0));
      out.push_back(s.getFloat64(PERISTEP_VR_BROKEN_BONDS).at(0));
    }
    return out;
  };
  const double before = s.getFloat64(PERISTEP_VR_BROKEN_BONDS).at(0);
  const std::vector<double> first = run();
  CHECK(first.back() > before);
  REQUIRE(s.fmu.fmi3SetFMUState(s.instance, state) == fmi3OK);
  CHECK(s.getFloat64(PERISTEP_VR_BROKEN_BONDS).at(0) == before);
  CHECK(run() == first);
  REQUIRE(s.fmu.fmi3FreeFMUState(s.instance, &state) == fmi3OK);
}

TEST_CASE("a specimen's modulus map carries the KL random field of xi", "[abi][specimen]") {
  // Two coordinates; the map is the inclusion plate's. With xi = 0 and the affine transform the factor is
  // exactly 1; with xi = (1.5, -1) it varies about the map, proportionally in the matrix and the inclusion.
  const auto modulus = [](std::vector<double> xi) {
    Session s;
    setUpNotchedPlate(s, true);
    REQUIRE(s.configure(kNx, kNy, 2) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_MATERIAL_FIELD, PERISTEP_MATERIAL_KL_FIELD) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_XI, xi) == fmi3OK);
    REQUIRE(s.initialize() == fmi3OK);
    std::int32_t laws[2] = {-1, -1};
    const fmi3ValueReference lawRef = PERISTEP_VR_XI_DISTRIBUTION;
    REQUIRE(s.fmu.fmi3GetInt32(s.instance, &lawRef, 1, laws, 2) == fmi3OK);
    CHECK(laws[0] == PERISTEP_XI_NORMAL);
    CHECK(laws[1] == PERISTEP_XI_NORMAL);
    const double retained = s.getFloat64(PERISTEP_VR_RETAINED_VARIANCE).at(0);
    CHECK(retained > 0);
    CHECK(retained < 1);
    return s.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, kPoints);
  };
  const std::vector<double> map = youngsModulus(true), plain = modulus({0.0, 0.0}), random = modulus({1.5, -1.0});
  CHECK(plain == map);
  double lowest = 2, highest = 0;
  for (std::size_t i = 0; i < kPoints; ++i) {
    lowest = std::min(lowest, random[i] / map[i]);
    highest = std::max(highest, random[i] / map[i]);
  }
  CHECK(lowest > 0);
  CHECK(highest - lowest > 0.1);
}

TEST_CASE("a bad specimen is refused with one precise message", "[abi][specimen][arguments]") {
  Session s;
  setUpNotchedPlate(s, true);
  const auto exitInit = [&] {
    REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3True, 1) == fmi3OK);
    return s.fmu.fmi3ExitInitializationMode(s.instance);
  };
  SECTION("a material map of the wrong length") {
    requireRefused(s, "fmi3SetFloat64", "nValues = 10 but the listed variables have 861 elements",
                   [&] { return s.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, std::vector<double>(10, 1e9)); });
  }
  SECTION("a negative modulus") {
    std::vector<double> E(kPoints, 1e9);
    E[7] = -1e9;
    requireRefused(s, "fmi3SetFloat64", "materialYoungsModulus (vr 80)[7] must lie in [0, inf), got -1e+09",
                   [&] { return s.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, E); });
  }
  SECTION("a pre-crack leaving the plate") {
    REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_X0, {-1.5}) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode",
                   "pre-crack 0 from (-1.5, -0.1) to (-0.6, 0.1) m leaves the plate [-1, 1] x [-0.5, 0.5] m", exitInit);
  }
  SECTION("a grip on a Void side") {
    std::vector<double> E(kPoints, 1e9);
    std::fill(E.end() - kNx, E.end(), 0.0);  // the top row is a free edge of Void
    REQUIRE(s.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, E) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode",
                   "the top grip holds a side along which materialYoungsModulus is 0 (Void): it would hold nothing",
                   exitInit);
  }
  SECTION("a horizon larger than the plate") {
    REQUIRE(s.setFloat64(PERISTEP_VR_DELTA_OVER_H, {20.0}) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode",
                   "the horizon deltaOverH * h = 1 m is not smaller than the plate (Lx = 2 m, Ly = 1 m)", exitInit);
  }
  SECTION("no held grip") {
    REQUIRE(s.setInt64(PERISTEP_VR_GRIP_BOTTOM, PERISTEP_GRIP_FREE) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_GRIP_TOP, PERISTEP_GRIP_FREE) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode", "every grip is free", exitInit);
  }
}
