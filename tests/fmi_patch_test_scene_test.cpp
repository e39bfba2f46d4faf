// Scene patchTest through the C ABI: the LPS discretization reproduces an affine field to round-off; the
// scene's own parameters and output reach an importer like any other.
#include <catch2/catch.hpp>

#include <cmath>

#include "fmi_abi_support.hpp"

namespace {

// patchError and the largest |ux - affine| after one step to loadFactor `load`.
double patchError(double jitter, double load) {
  Session s;
  REQUIRE(s.configure(13, 9) == fmi3OK);
  REQUIRE(s.setInt64(PERISTEP_VR_SCENE, PERISTEP_SCENE_PATCH_TEST) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LX, {1.2}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LY, {0.8}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_JITTER, {jitter}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_STRAIN_XX, {1e-3}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_STRAIN_YY, {-4e-4}) == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_STRAIN_XY, {2.5e-4}) == fmi3OK);
  REQUIRE(s.initialize() == fmi3OK);
  REQUIRE(s.setFloat64(PERISTEP_VR_LOAD_FACTOR, {load}) == fmi3OK);
  REQUIRE(s.step(0, 1) == fmi3OK);
  const std::vector<double> x = s.getFloat64(PERISTEP_VR_X, 13 * 9), y = s.getFloat64(PERISTEP_VR_Y, 13 * 9);
  const std::vector<double> ux = s.getFloat64(PERISTEP_VR_UX, 13 * 9);
  double worst = 0;
  for (std::size_t k = 0; k < ux.size(); ++k)
    worst = std::max(worst, std::abs(ux[k] - load * (1e-3 * x[k] + 2.5e-4 * y[k])));
  const double error = s.getFloat64(PERISTEP_VR_PATCH_ERROR).at(0);
  CHECK(worst <= error * load * 1e-3 * 0.6 * 2 + 1e-15);  // patchError bounds the x component too
  return error;
}

}  // namespace

TEST_CASE("patchTest: the affine field is reproduced to round-off", "[abi][patch]") {
  const double lattice = patchError(0.0, 1.0);
  INFO("patchError on the lattice " << lattice);
  CHECK(lattice < 1e-10);
  CHECK(patchError(0.0, 3.0) < 1e-10);
}

TEST_CASE("patchTest: its output is 0 in another scene, its bad parameters are refused", "[abi][patch]") {
  {
    Session s;
    REQUIRE(s.configure(9, 9) == fmi3OK);
    REQUIRE(s.initialize() == fmi3OK);
    REQUIRE(s.step(0, 1) == fmi3OK);
    CHECK(s.getFloat64(PERISTEP_VR_PATCH_ERROR).at(0) == 0.0);
  }
  Session s;
  CHECK(s.setFloat64(PERISTEP_VR_STRAIN_XX, {std::nan("")}) == fmi3Error);
  CHECK(s.log.errors() == 1);
}
