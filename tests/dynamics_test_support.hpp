#pragma once
// Small lattices and state-based models shared by the state-based and dynamics tests.
#include <cmath>
#include <random>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "models/state_based_model.hpp"
#include "scenes/dynamic_scene.hpp"

namespace peristep::testing {

// nx x ny lattice nodes at spacing h, centred at the origin, no collar (free edges).
inline PointCloud lattice(std::size_t nx, std::size_t ny, double h) {
  return cellCentredLattice(nx, ny, h, -0.5 * static_cast<double>(nx - 1) * h, -0.5 * static_cast<double>(ny - 1) * h);
}

inline StateBasedMaterial plexiglass(double nu, double eps, HydrostaticLaw law = HydrostaticLaw::Quadratic) {
  StateBasedInput in;
  in.poissonRatio = nu;
  in.law = law;
  if (law == HydrostaticLaw::ConvexConcave) {
    in.criticalDilatationPlus = 1e-3;
    in.criticalDilatationMinus = -1e-2;
  }
  return makeStateBasedMaterial(in, eps);
}

inline StateBasedModel model(const PointCloud& c, const StateBasedMaterial& m, double eps,
                             StateBasedBondOptions o = {}) {
  o.horizon = eps;
  return StateBasedModel(m, buildStateBasedBonds(c, o));
}

// Uniformly random field in [-amplitude, amplitude], reproducible.
inline std::vector<double> randomField(std::size_t n, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-amplitude, amplitude);
  std::vector<double> v(n);
  for (double& x : v) x = d(rng);
  return v;
}

}  // namespace peristep::testing
