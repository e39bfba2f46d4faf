// The glassCeramic scene is a preset of the specimen's variables (component/scenes/glass_ceramic.cpp): the
// same plate described as a specimen through the C ABI (grips, pre-crack, materialField glassCeramic,
// loadFactor = U_D) breaks the same bonds and reports the same outputs, bit for bit, at every step, for a
// microstructure and for the PCA field.
#include <catch2/catch.hpp>

#include "fmi_abi_support.hpp"

namespace {

constexpr std::uint64_t kNx = 51, kNy = 26;  // the paper's plate at h = 16 um
constexpr double kLx = 800e-6, kLy = 400e-6, kPreCrack = 100e-6, kStep = 4e-9;

void common(Session& s, std::int64_t scene, bool pca) {
  REQUIRE(s.configure(kNx, kNy, pca ? 3 : 1) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, scene) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {kLx}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {kLy}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_POISSON_RATIO, {0.25}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRYSTAL_FRACTION, {0.2}) == fmi3OK);
  if (pca) {
    REQUIRE(s.setUInt64(PERISTEP_VR_PCA_REALIZATIONS, 12) == fmi3OK);
    REQUIRE(s.setFloat64(PERISTEP_VR_XI, {0.8, -0.5, 0.3}) == fmi3OK);
  }
}

// The preset spelled out: bottom and top held and moved by -1 and +1 m per unit load in y, left and right
// free (the start values), the pre-crack from 2 delta beyond the left edge to its tip.
void asSpecimen(Session& s, bool pca) {
  REQUIRE(s.configureStructural({PERISTEP_VR_NCRACKS}, {1}) == fmi3OK);
  common(s, PERISTEP_SCENE_SPECIMEN, pca);
  REQUIRE(s.setInt64(PERISTEP_VR_MATERIAL_FIELD, PERISTEP_MATERIAL_GLASS_CERAMIC) == fmi3OK);
  const double h = kLx / (kNx - 1), left = -0.5 * kLx;
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_X0, {left - 2.0 * (3.0 * h)}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_Y0, {0.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_X1, {left + kPreCrack}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_CRACK_Y1, {0.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOTTOM_UX, {0.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_BOTTOM_UY, {-1.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_TOP_UX, {0.0}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_GRIP_TOP_UY, {1.0}) == fmi3OK);
  // Initialization solves at the inputs: start unloaded (loadFactor's start value 1 would mean 1 m).
  REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {0.0}) == fmi3OK);
}

void compareRuns(bool pca) {
  Session scene, specimen;
  common(scene, PERISTEP_SCENE_GLASS_CERAMIC, pca);
  asSpecimen(specimen, pca);
  REQUIRE(scene.initialize(0, 100) == fmi3OK);
  REQUIRE(specimen.initialize(0, 100) == fmi3OK);
  const std::size_t n = kNx * kNy;
  CHECK(specimen.getFloat64(PERISTEP_VR_XI_SCALE, pca ? 3 : 1) == scene.getFloat64(PERISTEP_VR_XI_SCALE, pca ? 3 : 1));
  CHECK(specimen.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, n) == scene.getFloat64(PERISTEP_VR_YOUNGS_MODULUS, n));
  int step = 0, cracked = 0;
  for (; step < 100 && !scene.testOver; ++step) {
    const double UD = kStep * (step + 1);
    REQUIRE(scene.setFloat64(PERISTEP_VR_LOAD_DISPLACEMENT, {UD}) == fmi3OK);
    REQUIRE(specimen.setFloat64(PERISTEP_VR_LOAD_FACTOR, {UD}) == fmi3OK);
    REQUIRE(scene.step(step, 1) == fmi3OK);
    REQUIRE(specimen.step(step, 1) == fmi3OK);
    INFO("step " << step << ", U_D = " << UD);
    for (fmi3ValueReference vr : {PERISTEP_VR_BROKEN_BONDS, PERISTEP_VR_CRACK_LENGTH, PERISTEP_VR_TOUGHNESS_KIC,
                                  PERISTEP_VR_FRACTURE_ENERGY, PERISTEP_VR_REACTION_FORCE,
                                  PERISTEP_VR_REACTION_BOTTOM_Y})
      REQUIRE(specimen.getFloat64(vr) == scene.getFloat64(vr));
    for (fmi3ValueReference vr : {PERISTEP_VR_UX, PERISTEP_VR_UY, PERISTEP_VR_DAMAGE})
      REQUIRE(specimen.getFloat64(vr, n) == scene.getFloat64(vr, n));
    REQUIRE(specimen.testOver == scene.testOver);
    if (scene.getFloat64(PERISTEP_VR_CRACK_LENGTH).at(0) > 0) ++cracked;
  }
  CHECK(scene.testOver);  // the crack crossed the plate: the comparison covered its growth
  CHECK(cracked > 3);
  CHECK(scene.getFloat64(PERISTEP_VR_TOUGHNESS_KIC).at(0) > 0);
}

}  // namespace

TEST_CASE("the glassCeramic scene equals the specimen with its preset's variables, bit for bit", "[abi][specimen]") {
  SECTION("microstructure of seed 1") { compareRuns(false); }
  SECTION("PCA field of 12 microstructures at three coordinates") { compareRuns(true); }
}
