#include <catch2/catch.hpp>

#include "core/errors.hpp"
#include "models/state_based_material.hpp"

using namespace peristep;

namespace {
StateBasedMaterial table1(double nu) {
  StateBasedInput in;  // K = 25 GPa, G_c = 500 J/m^2, rho = 1200 kg/m^3 (001 Table 1)
  in.poissonRatio = nu;
  return makeStateBasedMaterial(in, 0.002);
}
}  // namespace

TEST_CASE("001 Table 1, column nu = 0.25: c, beta, C and r*", "[state_based]") {
  const StateBasedMaterial m = table1(0.25);
  CHECK(m.f.c == Approx(4712.4).epsilon(1e-5));
  CHECK(m.f.beta == Approx(1.5279e8).epsilon(1e-4));
  CHECK(m.g.C == 0.0);  // lambda = mu: no hydrostatic force at all
  CHECK(m.f.inflection() == Approx(5.7206e-5).epsilon(1e-4));
  // The relations of DESIGN 5.5 run backwards give the input back.
  CHECK(m.fractureEnergy() == Approx(500.0).epsilon(1e-12));
  CHECK(m.shearModulus() == Approx(15e9).epsilon(1e-12));
  CHECK(m.lameLambda() == Approx(15e9).epsilon(1e-9));
}

TEST_CASE("001 Table 1, column printed as nu = 0.245, is reproduced by nu = 0.22", "[state_based]") {
  // Misprint in 001 Table 1: the column labelled nu = 0.245 is what nu = 0.22 gives (DESIGN 5.5).
  const StateBasedMaterial m = table1(0.22);
  CHECK(m.f.c == Approx(4712.4).epsilon(1e-5));
  CHECK(m.f.beta == Approx(1.7533e8).epsilon(1e-4));
  CHECK(m.g.C == Approx(-1.0623e12).epsilon(1e-4));
  CHECK(m.f.inflection() == Approx(5.3402e-5).epsilon(1e-4));
  // The printed label itself does not give the printed numbers.
  const StateBasedMaterial printed = table1(0.245);
  CHECK(std::abs(printed.f.beta / 1.7533e8 - 1.0) > 0.05);
  CHECK(std::abs(printed.g.C / -1.0623e12 - 1.0) > 0.5);
}

TEST_CASE("state-based material input is validated", "[state_based]") {
  StateBasedInput in;
  in.bulkModulus = -1;
  CHECK_THROWS_AS(makeStateBasedMaterial(in, 0.002), InvalidInput);
  in = {};
  in.poissonRatio = 0.5;
  CHECK_THROWS_AS(makeStateBasedMaterial(in, 0.002), InvalidInput);
  in = {};
  in.fractureEnergy = 0;
  CHECK_THROWS_AS(makeStateBasedMaterial(in, 0.002), InvalidInput);
  in = {};
  in.density = std::nan("");
  CHECK_THROWS_AS(makeStateBasedMaterial(in, 0.002), InvalidInput);
  // Convex-concave hydrostatic law: needs C > 0 (nu > 0.25) and critical strains of the right sign.
  in = {};
  in.law = HydrostaticLaw::ConvexConcave;
  in.criticalDilatationPlus = 1e-3;
  in.criticalDilatationMinus = -1e-2;
  in.poissonRatio = 0.22;
  CHECK_THROWS_AS(makeStateBasedMaterial(in, 0.002), InvalidInput);
  in.poissonRatio = 0.3;
  const StateBasedMaterial m = makeStateBasedMaterial(in, 0.002);
  // Inflection of g at theta_c = eps M2 tr(E)_c, where its force starts to soften (001:(9)).
  const double thetaC = 0.002 * kStateBasedM2 * 1e-3;
  CHECK(m.g.curvature(thetaC) == Approx(0.0).margin(1e-9 * m.g.C));
  CHECK(m.g.curvature(0.5 * thetaC) > 0);
  CHECK(m.g.curvature(1.5 * thetaC) < 0);
  CHECK(m.g.curvature(-5 * thetaC) > 0);  // compressive softening comes much later
  in.criticalDilatationMinus = 1e-2;
  CHECK_THROWS_AS(makeStateBasedMaterial(in, 0.002), InvalidInput);
}
