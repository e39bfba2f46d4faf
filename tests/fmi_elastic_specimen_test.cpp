// The specimen's elastic model, its collar gradient and its exact solutions through the C ABI: the klPlate,
// smooth, composite and interfaceCrack scenes are presets of them (the same plates set as specimens give their outputs bit
// for bit); a homogeneous plate whose collars
// carry a linear field is solved exactly (LPS with the weights of 000:(3.18) is exact for linear fields);
// the notched plate with an inclusion, Void and pre-crack included, solves as the fracture model's first
// step before anything breaks.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "fmi_abi_support.hpp"
#include "fmi_refusal.hpp"
#include "fmi_notched_plate.hpp"

namespace {

void holdAllSides(Session& s) {
  for (fmi3ValueReference vr : {PERISTEP_VR_GRIP_LEFT, PERISTEP_VR_GRIP_RIGHT, PERISTEP_VR_GRIP_BOTTOM, PERISTEP_VR_GRIP_TOP})
    REQUIRE(s.setInt64(vr, PERISTEP_GRIP_HELD) == fmi3OK);
  for (fmi3ValueReference vr : {PERISTEP_VR_GRIP_LEFT_UY, PERISTEP_VR_GRIP_RIGHT_UY, PERISTEP_VR_GRIP_BOTTOM_UY,
                                PERISTEP_VR_GRIP_TOP_UY})
    REQUIRE(s.setFloat64(vr, {0.0}) == fmi3OK);
}

void setGradient(Session& s, const std::array<double, 4>& G) {
  const fmi3ValueReference vr[] = {PERISTEP_VR_COLLAR_DUX_DX, PERISTEP_VR_COLLAR_DUX_DY, PERISTEP_VR_COLLAR_DUY_DX,
                                   PERISTEP_VR_COLLAR_DUY_DY};
  for (std::size_t k = 0; k < 4; ++k) REQUIRE(s.setFloat64(vr[k], {G[k]}) == fmi3OK);
}

constexpr std::uint64_t kNx = 21, kNy = 17;
constexpr std::size_t kN = kNx * kNy;

// A 2 x 1.6 m elastic specimen on the kNx x kNy grid (h = 0.1 m); grips at their start values.
void elasticPlate(Session& s) {
  REQUIRE(s.configure(kNx, kNy, 1) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_SPECIMEN) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_ELASTIC) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {2.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {1.6}) == fmi3OK);
}

// Shared by the scene and its spelled-out specimen: grid, plate, field and its three coordinates.
void klCommon(Session& s, std::int64_t scene) {
  REQUIRE(s.configure(kNx, kNy, 3) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, scene) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {1.25}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {1.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.28}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_FIELD_STD, {0.3}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CORRELATION_LENGTH, {0.4}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_XI, {0.9, -1.2, 0.4}) == fmi3OK);
}

}  // namespace

TEST_CASE("the klPlate scene equals the elastic specimen with its preset's variables, bit for bit",
          "[abi][specimen]") {
  Session scene, specimen;
  klCommon(scene, PERISTEP_SCENE_KL_PLATE);
  klCommon(specimen, PERISTEP_SCENE_SPECIMEN);
  REQUIRE(specimen.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_ELASTIC) == fmi3OK);
  REQUIRE(specimen.setInt64(PERISTEP_VR_MATERIAL_FIELD, PERISTEP_MATERIAL_KL_FIELD) == fmi3OK);
  REQUIRE(specimen.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, std::vector<double>(kN, 1.0)) == fmi3OK);
  REQUIRE(specimen.setFloat64(PERISTEP_VR_MATERIAL_POISSON_RATIO, std::vector<double>(kN, 0.28)) == fmi3OK);
  holdAllSides(specimen);
  setGradient(specimen, {0, 0, 0, 0.01});
  REQUIRE(scene.initialize(0, 10) == fmi3OK);
  REQUIRE(specimen.initialize(0, 10) == fmi3OK);
  CHECK(specimen.getFloat64(PERISTEP_VR_RETAINED_VARIANCE) == scene.getFloat64(PERISTEP_VR_RETAINED_VARIANCE));
  CHECK(specimen.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, kN) == scene.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, kN));
  for (int step = 0; step < 2; ++step) {
    const double load = step == 0 ? 1.0 : -0.5;
    REQUIRE(scene.setFloat64(PERISTEP_VR_LOAD_FACTOR, {load}) == fmi3OK);
    REQUIRE(specimen.setFloat64(PERISTEP_VR_LOAD_FACTOR, {load}) == fmi3OK);
    REQUIRE(scene.step(step, 1) == fmi3OK);
    REQUIRE(specimen.step(step, 1) == fmi3OK);
    for (fmi3ValueReference vr : {PERISTEP_VR_UX, PERISTEP_VR_UY})
      CHECK(specimen.getFloat64(vr, kN) == scene.getFloat64(vr, kN));
    for (fmi3ValueReference vr : {PERISTEP_VR_REACTION_TOP_Y, PERISTEP_VR_REACTION_LEFT_X})
      CHECK(specimen.getFloat64(vr) == scene.getFloat64(vr));
    // The plate is stretched in y: the top collar pulls up at load > 0, and the four collars' y-forces
    // balance (the side collars hold the plate's ends in shear).
    const double top = scene.getFloat64(PERISTEP_VR_REACTION_TOP_Y).at(0);
    CHECK(top * load > 0);
    double sum = 0;
    for (fmi3ValueReference vr : {PERISTEP_VR_REACTION_LEFT_Y, PERISTEP_VR_REACTION_RIGHT_Y,
                                  PERISTEP_VR_REACTION_BOTTOM_Y, PERISTEP_VR_REACTION_TOP_Y})
      sum += scene.getFloat64(vr).at(0);
    INFO("sum of the y-reactions " << sum << " N/m, top " << top << " N/m");
    CHECK(std::abs(sum) <= 0.01 * std::abs(top));
    CHECK(scene.getFloat64(PERISTEP_VR_BROKEN_BONDS).at(0) == 0.0);
  }
}

TEST_CASE("Tests 1-3 equal the elastic specimen with their exact solutions, bit for bit", "[abi][specimen]") {
  constexpr std::uint64_t n1 = 17;
  const double pi = 3.141592653589793;
  for (const auto& [scene, exact, nModes] :
       {std::tuple{PERISTEP_SCENE_SMOOTH, PERISTEP_EXACT_SMOOTH, 1}, {PERISTEP_SCENE_COMPOSITE, PERISTEP_EXACT_COMPOSITE, 2},
        {PERISTEP_SCENE_INTERFACE_CRACK, PERISTEP_EXACT_INTERFACE_CRACK, 2}}) {
    INFO("scene " << scene);
    const bool test3 = scene == PERISTEP_SCENE_INTERFACE_CRACK;
    const double L = test3 ? pi : 1.0;  // Test 3 on [-pi/2, pi/2]^2 as in 000 Sec. 4.3
    const auto setUp = [&](Session& s, std::int64_t which) {
      REQUIRE(s.configure(n1, n1, static_cast<std::uint64_t>(nModes)) == fmi3OK);
      REQUIRE(s.setInt64(PERISTEP_VR_SCENE, which) == fmi3OK);
      REQUIRE(s.setFloat64(PERISTEP_VR_LX, {L}) == fmi3OK);
      REQUIRE(s.setFloat64(PERISTEP_VR_LY, {L}) == fmi3OK);
      const std::vector<double> xi{0.6, -0.7};
      REQUIRE(s.setFloat64(PERISTEP_VR_XI, {xi.begin(), xi.begin() + nModes}) == fmi3OK);
      REQUIRE(s.setFloat64(PERISTEP_VR_MODULUS_CONTRAST, {3.0}) == fmi3OK);
    };
    Session builtIn, specimen;
    setUp(builtIn, scene);
    setUp(specimen, PERISTEP_SCENE_SPECIMEN);
    REQUIRE(specimen.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_ELASTIC) == fmi3OK);
    REQUIRE(specimen.setInt64(PERISTEP_VR_EXACT_SOLUTION, exact) == fmi3OK);
    holdAllSides(specimen);
    if (test3) {  // the interface crack from the collar's outer edge (2 delta beyond the left side) to the origin
      const double h = L / (n1 - 1);
      REQUIRE(specimen.setFloat64(PERISTEP_VR_CRACK_X0, {-0.5 * L - 2.0 * 3.0 * h}) == fmi3OK);
      for (fmi3ValueReference vr : {PERISTEP_VR_CRACK_Y0, PERISTEP_VR_CRACK_X1, PERISTEP_VR_CRACK_Y1})
        REQUIRE(specimen.setFloat64(vr, {0.0}) == fmi3OK);
    }
    REQUIRE(builtIn.initialize(0, 10) == fmi3OK);
    REQUIRE(specimen.initialize(0, 10) == fmi3OK);
    const std::size_t n = n1 * n1;
    CHECK(specimen.getFloat64(PERISTEP_VR_XI_SCALE, nModes) == builtIn.getFloat64(PERISTEP_VR_XI_SCALE, nModes));
    CHECK(specimen.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, n) == builtIn.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, n));
    REQUIRE(builtIn.step(0, 1) == fmi3OK);
    REQUIRE(specimen.step(0, 1) == fmi3OK);
    for (fmi3ValueReference vr : {PERISTEP_VR_UX, PERISTEP_VR_UY, PERISTEP_VR_DAMAGE, PERISTEP_VR_EXACT_MEAN_UX,
                                  PERISTEP_VR_EXACT_STD_UY})
      CHECK(specimen.getFloat64(vr, n) == builtIn.getFloat64(vr, n));
    for (fmi3ValueReference vr : {PERISTEP_VR_ERROR_L2, PERISTEP_VR_BROKEN_BONDS, PERISTEP_VR_REACTION_TOP_Y,
                                  PERISTEP_VR_REACTION_LEFT_X})
      CHECK(specimen.getFloat64(vr) == builtIn.getFloat64(vr));
    // The exact solution is matched to the discretization error, and only Test 3 has cut bonds.
    const double error = builtIn.getFloat64(PERISTEP_VR_ERROR_L2).at(0);
    CHECK(error > 0);
    CHECK(error < 0.1);
    CHECK((builtIn.getFloat64(PERISTEP_VR_BROKEN_BONDS).at(0) > 0) == test3);
  }
}

TEST_CASE("an elastic specimen whose collars carry a linear field takes that field exactly", "[abi][specimen]") {
  // A homogeneous plate, every side held with a gradient of stretch, shear and rotation; no body force, so
  // the linear field solves the local problem and LPS with the weights of 000:(3.18) reproduces it.
  const std::array<double, 4> G{2e-3, 1.5e-3, -0.5e-3, 3e-3};
  Session s;
  elasticPlate(s);
  REQUIRE(s.setFloat64(PERISTEP_VR_JITTER, {0.2}) == fmi3OK);  // on a jittered cloud as well
  holdAllSides(s);
  setGradient(s, G);
  REQUIRE(s.initialize() == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {2.0}) == fmi3OK);
  REQUIRE(s.step(0, 1) == fmi3OK);
  const auto x = s.getFloat64(PERISTEP_VR_X, kN), y = s.getFloat64(PERISTEP_VR_Y, kN);
  const auto ux = s.getFloat64(PERISTEP_VR_UX, kN), uy = s.getFloat64(PERISTEP_VR_UY, kN);
  double worst = 0, largest = 0;
  for (std::size_t i = 0; i < kN; ++i) {
    const double ex = 2.0 * (G[0] * x[i] + G[1] * y[i]), ey = 2.0 * (G[2] * x[i] + G[3] * y[i]);
    worst = std::max({worst, std::abs(ux[i] - ex), std::abs(uy[i] - ey)});
    largest = std::max({largest, std::abs(ex), std::abs(ey)});
  }
  INFO("largest deviation " << worst << " m of displacements up to " << largest << " m");
  CHECK(worst <= 1e-10 * largest);
  CHECK(s.getFloat64(PERISTEP_VR_DAMAGE, kN) == std::vector<double>(kN, 0.0));
}

TEST_CASE("an elastic notched plate with an inclusion and a hole solves as the fracture model before a break",
          "[abi][specimen]") {
  using namespace notched_plate;
  // The hole: Void points in a disc below the inclusion.
  std::vector<double> E = youngsModulus(true);
  for (std::size_t i = 0; i < kPoints; ++i)
    if (std::hypot(xOf(i) - 0.5, yOf(i) + 0.25) <= 0.12) E[i] = 0.0;
  const auto solve = [&](std::int64_t model) {
    Session s;
    REQUIRE(s.configure(notched_plate::kNx, notched_plate::kNy, 1) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_SPECIMEN) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, model) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LX, {kLx}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LY, {kLy}) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, E) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_MATERIAL_FRACTURE_ENERGY, fractureEnergy(true)) == fmi3OK);
    setNotch(s);
    REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_TOP_UY, {kTopPull}) == fmi3OK);
    REQUIRE(s.initialize() == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {3.5}) == fmi3OK);  // below the first break (fmi_specimen_test)
    REQUIRE(s.step(0, 1) == fmi3OK);
    std::vector<double> out = s.getFloat64(PERISTEP_VR_UY, kPoints);
    out.push_back(s.getFloat64(PERISTEP_VR_REACTION_TOP_Y).at(0));
    out.push_back(s.getFloat64(PERISTEP_VR_BROKEN_BONDS).at(0));
    return out;
  };
  const std::vector<double> elastic = solve(PERISTEP_SPECIMEN_ELASTIC), fracture = solve(PERISTEP_SPECIMEN_QUASI_STATIC);
  CHECK(fracture.back() > 0.0);  // the notch's bonds, which both models report
  CHECK(elastic.back() == fracture.back());
  // The fracture model adds springs of 1e-8 relative stiffness where bonds are broken (the notch, the hole's
  // rim), and its solver differs: the fields agree to that order, the top grip's reaction as well.
  double worst = 0, largest = 0;
  for (std::size_t i = 0; i < kPoints; ++i) {
    worst = std::max(worst, std::abs(elastic[i] - fracture[i]));
    largest = std::max(largest, std::abs(fracture[i]));
  }
  INFO("largest difference " << worst << " m of uy up to " << largest << " m");
  CHECK(largest > 0.5 * 3.5 * kTopPull);
  CHECK(worst <= 1e-6 * largest);
  CHECK(elastic[kPoints] == Approx(fracture[kPoints]).epsilon(1e-6));
  for (std::size_t i = 0; i < kPoints; ++i)
    if (E[i] == 0.0) CHECK(elastic[i] == 0.0);  // Void reads 0
}

TEST_CASE("a collar gradient that cannot apply is refused with one precise message", "[abi][specimen][arguments]") {
  Session s;
  REQUIRE(s.configure(kNx, kNy, 1) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_SPECIMEN) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {2.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {1.6}) == fmi3OK);
  const auto exitInit = [&] {
    REQUIRE(s.fmu.fmi3EnterInitializationMode(s.instance, fmi3False, 0, 0, fmi3True, 1) == fmi3OK);
    return s.fmu.fmi3ExitInitializationMode(s.instance);
  };
  SECTION("given to the dynamic model") {
    REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_DYNAMIC) == fmi3OK);
    setGradient(s, {0, 0, 0, 1e-3});
    requireRefused(s, "fmi3ExitInitializationMode", "the dynamic model's grips move at gripVx, gripVy", exitInit);
  }
  SECTION("not a number") {
    requireRefused(s, "fmi3SetFloat64", "collarDuyDx", [&] { return s.setFloat64(PERISTEP_VR_COLLAR_DUY_DX, {NAN}); });
  }
  SECTION("an exact solution on a plate with a free side") {
    REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_ELASTIC) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_EXACT_SOLUTION, PERISTEP_EXACT_SMOOTH) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode", "it needs specimenModel elastic, every side held", exitInit);
  }
  SECTION("an exact solution with the fracture model") {
    holdAllSides(s);
    REQUIRE(s.setInt64(PERISTEP_VR_EXACT_SOLUTION, PERISTEP_EXACT_COMPOSITE) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode", "it needs specimenModel elastic, every side held", exitInit);
  }
  SECTION("the generated glass-ceramic with the dynamic model") {
    REQUIRE(s.setInt64(PERISTEP_VR_SPECIMEN_MODEL, PERISTEP_SPECIMEN_DYNAMIC) == fmi3OK);
    REQUIRE(s.setInt64(PERISTEP_VR_MATERIAL_FIELD, PERISTEP_MATERIAL_GLASS_CERAMIC) == fmi3OK);
    requireRefused(s, "fmi3ExitInitializationMode", "materialField glassCeramic is for the quasi-static models",
                   exitInit);
  }
}

TEST_CASE("an elastic specimen with a floating island leaves it at rest, and every value finite",
          "[abi][specimen]") {
  // A Void ring (wider than the horizon) cuts an island out of the plate: nothing holds it and nothing loads
  // it; the set-up holds it at rest (models/unheld_pieces.hpp) instead of leaving a singular block to the
  // solver. (The fracture model holds such pieces by its springs.)
  const auto onIsland = [](std::size_t i) {
    const double x = -1.0 + 0.1 * static_cast<double>(i % kNx), y = -0.8 + 0.1 * static_cast<double>(i / kNx);
    return std::hypot(x, y) <= 0.25;
  };
  std::vector<double> E(kN, 1e9);
  for (std::size_t i = 0; i < kN; ++i) {
    const double x = -1.0 + 0.1 * static_cast<double>(i % kNx), y = -0.8 + 0.1 * static_cast<double>(i / kNx);
    if (!onIsland(i) && std::hypot(x, y) < 0.6) E[i] = 0.0;
  }
  Session s;
  elasticPlate(s);
  REQUIRE(s.setFloat64(PERISTEP_VR_MATERIAL_YOUNGS_MODULUS, E) == fmi3OK);
  REQUIRE(s.initialize(0, 10) == fmi3OK);
  REQUIRE(s.step(0, 1) == fmi3OK);
  const auto uy = s.getFloat64(PERISTEP_VR_UY, kN), ux = s.getFloat64(PERISTEP_VR_UX, kN);
  std::size_t island = 0;
  double largest = 0;
  for (std::size_t i = 0; i < kN; ++i) {
    REQUIRE(std::isfinite(ux[i]));
    REQUIRE(std::isfinite(uy[i]));
    largest = std::max(largest, std::abs(uy[i]));
    if (!onIsland(i)) continue;
    ++island;
    CHECK(ux[i] == 0.0);
    CHECK(uy[i] == 0.0);
  }
  CHECK(island >= 13);
  CHECK(largest > 0.5e-6);  // the rest of the plate is pulled (top grip 1e-6 m)
}
