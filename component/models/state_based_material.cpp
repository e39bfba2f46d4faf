#include "models/state_based_material.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "models/poisson_ratio.hpp"

namespace peristep {

double StateBasedMaterial::fractureEnergy() const { return 4.0 * f.c * kStateBasedM2 / std::numbers::pi; }

StateBasedMaterial makeStateBasedMaterial(const StateBasedInput& in, double horizon) {
  using std::to_string;
  const double K = in.bulkModulus, nu = in.poissonRatio, Gc = in.fractureEnergy;
  require(std::isfinite(K) && K > 0, "state-based material: bulk modulus must be positive (got " + to_string(K) + ")");
  require(admissiblePoissonRatio(nu),
          "state-based material: Poisson ratio must lie in (-1, 0.5) (got " + to_string(nu) + ")");
  require(std::isfinite(Gc) && Gc > 0, "state-based material: G_c must be positive (got " + to_string(Gc) + ")");
  require(std::isfinite(in.density) && in.density > 0,
          "state-based material: density must be positive (got " + to_string(in.density) + ")");
  require(std::isfinite(horizon) && horizon > 0, "state-based material: horizon must be positive");

  const double M2 = kStateBasedM2, pi = std::numbers::pi;
  const double mu = 3.0 * K * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
  const double lambda = 3.0 * K * nu / (1.0 + nu);
  StateBasedMaterial m;
  m.density = in.density;
  m.f.c = pi * Gc / (4.0 * M2);
  m.f.beta = 16.0 * mu / (pi * Gc);
  m.g.law = in.law;
  // lambda = mu (nu = 0.25) switches the hydrostatic force off; do not let round-off keep it alive.
  m.g.C = std::abs(lambda - mu) <= 1e-12 * mu ? 0.0 : 2.0 * (lambda - mu) / (M2 * M2);
  if (in.law == HydrostaticLaw::ConvexConcave) {
    require(m.g.C > 0, "state-based material: the convex-concave hydrostatic law needs C > 0, i.e. nu > 0.25 (got nu = " +
                           to_string(nu) + ")");
    require(in.criticalDilatationPlus > 0 && std::isfinite(in.criticalDilatationPlus),
            "state-based material: criticalDilatationPlus must be positive and finite");
    require(in.criticalDilatationMinus < 0 && std::isfinite(in.criticalDilatationMinus),
            "state-based material: criticalDilatationMinus must be negative and finite");
    // theta = eps M2 tr(E) for a homogeneous strain; inflection of g at theta_c = 1/sqrt(2 b).
    const double tp = horizon * M2 * in.criticalDilatationPlus, tm = horizon * M2 * in.criticalDilatationMinus;
    m.g.bPlus = 1.0 / (2.0 * tp * tp);
    m.g.bMinus = 1.0 / (2.0 * tm * tm);
  }
  return m;
}

}  // namespace peristep
