#include "scenes/kl_plate.hpp"

namespace peristep {

namespace {
constexpr double kMeanModulus = 1.0;  // E0
constexpr double kStretch = 0.01;     // du_y/dy of the collar
}  // namespace

SpecimenSpec klPlatePreset(const GridSpec& g, double nu) {
  SpecimenSpec s;
  s.model = SpecimenModel::Elastic;
  s.material = SpecimenMaterial::KlField;
  const std::size_t n = g.nx * g.ny;
  s.youngsModulus.assign(n, kMeanModulus);
  s.poissonRatio.assign(n, nu);
  s.fractureEnergy.assign(n, 1.0);  // not read by the elastic model
  s.density.assign(n, 1.0);         // nor this
  for (Grip& grip : s.grips) grip.held = true;
  s.collarGradient = {0, 0, 0, kStretch};
  return s;
}

}  // namespace peristep
