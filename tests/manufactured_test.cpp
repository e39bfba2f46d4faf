// The exact solutions of Tests 1 and 2 satisfy their own equations (DESIGN 5.1, 5.4).
#include <catch2/catch.hpp>
#include <cmath>

#include "models/lps_material.hpp"
#include "scenes/manufactured.hpp"

using namespace peristep;

namespace {

// sigma(u0) by central differences of the scene's displacement and modulus.
std::array<double, 3> stress(const ElasticScene& s, double x, double y, double e = 1e-6) {
  const Vec2 ux0 = s.displacement(x - e, y), ux1 = s.displacement(x + e, y);
  const Vec2 uy0 = s.displacement(x, y - e), uy1 = s.displacement(x, y + e);
  const double exx = (ux1[0] - ux0[0]) / (2 * e), eyy = (uy1[1] - uy0[1]) / (2 * e);
  const double exy = 0.5 * ((uy1[0] - uy0[0]) + (ux1[1] - ux0[1])) / (2 * e);
  const Lame l = planeStrain(s.youngsModulus(x, y), s.poissonRatio());
  return {l.lambda * (exx + eyy) + 2 * l.mu * exx, l.lambda * (exx + eyy) + 2 * l.mu * eyy, 2 * l.mu * exy};
}

}  // namespace

TEST_CASE("Test 1 body force is -div sigma(u0) and does not depend on xi", "[scenes]") {
  const double nu = GENERATE(0.3, 0.495);
  const SmoothScene a(nu, 0.0), b(nu, 0.1);
  const double e = 1e-4;
  for (double x : {-0.4, -0.1, 0.2, 0.45})
    for (double y : {-0.3, 0.05, 0.35}) {
      const auto sx0 = stress(a, x - e, y), sx1 = stress(a, x + e, y);
      const auto sy0 = stress(a, x, y - e), sy1 = stress(a, x, y + e);
      const double divX = (sx1[0] - sx0[0]) / (2 * e) + (sy1[2] - sy0[2]) / (2 * e);
      const double divY = (sx1[2] - sx0[2]) / (2 * e) + (sy1[1] - sy0[1]) / (2 * e);
      const Vec2 f = a.bodyForce(x, y);
      const double scale = 1.0 / (1 - 2 * nu);
      CHECK(f[0] == Approx(-divX).margin(1e-5 * scale));
      CHECK(f[1] == Approx(-divY).margin(1e-5 * scale));
      CHECK(b.bodyForce(x, y)[0] == Approx(f[0]));
    }
}

TEST_CASE("Test 2 field is continuous with continuous traction across x = 0", "[scenes]") {
  const double contrast = GENERATE(2.0, 1e6);
  const CompositeScene s(0.3, 0.7, -1.2, contrast);
  for (double y : {-1.0, 0.0, 1.3}) {
    const double e = 1e-3;
    const Vec2 left = s.displacement(-e, y), right = s.displacement(e, y);
    CHECK(left[0] == Approx(0.0).margin(1e-2));
    CHECK(right[0] == Approx(0.0).margin(1e-2));
    const auto sl = stress(s, -0.5, y), sr = stress(s, 0.5, y);  // fields are linear on each side
    CHECK(sl[0] == Approx(sr[0]).epsilon(1e-6));                 // sigma_xx
    CHECK(sl[2] == Approx(sr[2]).epsilon(1e-6));                 // sigma_xy
  }
}
