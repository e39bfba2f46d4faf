#pragma once
// Material constants of the nonlinear state-based model (001 Sec. 6, Table 1; DESIGN 5.5).
#include <limits>

#include "models/state_based_potentials.hpp"

namespace peristep {

// M2 = int_0^1 r^2 J(r) dr for J(r) = 1 - r.
inline constexpr double kStateBasedM2 = 1.0 / 12.0;

struct StateBasedMaterial {
  double density = 0;    // kg/m^3
  TensilePotential f;    // c [N/m], beta [1/m]
  HydrostaticPotential g;

  // The relations of 001 Sec. 6 (Eqs. (94), (95), (97) of its Ref. [20]) in 2D with M2 = 1/12:
  //   mu = c beta M2/4,  lambda = mu + C M2^2/2,  G_c = 4 c M2/pi.
  // These are the constants Table 1 is computed with. Note: the small-strain limit of the force
  // 001:(14)-(15) as printed (with its factor 2 and the energy 001:(11)) has Lame constants twice these
  // (mu_PD = c beta M2/2, lambda_PD = mu_PD + C M2^2), while G_c = 4 c M2/pi is exactly the energy
  // 001:(11) of a straight fully softened crack; see peridynamicLame() and the model tests.
  double shearModulus() const { return f.c * f.beta * kStateBasedM2 / 4.0; }
  double lameLambda() const { return shearModulus() + g.C * kStateBasedM2 * kStateBasedM2 / 2.0; }
  double fractureEnergy() const;
  // Lame constants of the small-strain limit of 001:(11) (computed, not the Table 1 convention).
  double peridynamicShearModulus() const { return 2.0 * shearModulus(); }
  double peridynamicLambda() const { return 2.0 * lameLambda(); }
};

struct StateBasedInput {
  double bulkModulus = 25e9;        // K [Pa]
  double poissonRatio = 0.25;       // nu (3D relations K, nu -> lambda, mu, as Table 1 does)
  double fractureEnergy = 500.0;    // G_c [J/m^2]
  double density = 1200.0;          // rho [kg/m^3]
  HydrostaticLaw law = HydrostaticLaw::Quadratic;
  // Convex-concave law only: volumetric strains tr(E) at which the hydrostatic force starts to soften
  // (001:(9) with theta = eps M2 tr(E) for a homogeneous strain); |minus| >> plus per 001 Sec. 2.1.
  double criticalDilatationPlus = std::numeric_limits<double>::infinity();
  double criticalDilatationMinus = -std::numeric_limits<double>::infinity();
};

// c = pi G_c/(4 M2), beta = 16 mu/(pi G_c), C = 2 (lambda - mu)/M2^2 (DESIGN 5.5).
// horizon is needed only to place the convex-concave inflection points in theta units.
// Throws InvalidInput for non-physical input (K, G_c, rho <= 0, nu outside (-1, 0.5), a convex-concave
// law with C <= 0, i.e. nu <= 0.25, or critical strains of the wrong sign).
StateBasedMaterial makeStateBasedMaterial(const StateBasedInput& in, double horizon);

}  // namespace peristep
