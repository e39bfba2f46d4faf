#include "scenes/glass_ceramic.hpp"

#include "fracture/bond_state.hpp"
#include "scenes/glass_ceramic_material.hpp"

namespace peristep {

SpecimenSpec glassCeramicPreset(const GridSpec& g, double preCrackLength) {
  SpecimenSpec s;
  s.grips[static_cast<std::size_t>(Side::Bottom)] = {.held = true, .ux = 0, .uy = -1};
  s.grips[static_cast<std::size_t>(Side::Top)] = {.held = true, .ux = 0, .uy = 1};
  const double left = -0.5 * g.Lx;
  if (preCrackLength > 0) s.cracks.push_back({left - 2.0 * g.delta(), 0.0, left + preCrackLength, 0.0});
  s.material = SpecimenMaterial::GlassCeramic;
  s.load = SpecimenLoad::LoadDisplacement;
  return s;
}

GlassCeramicSpecimen::GlassCeramicSpecimen(const GlassCeramicSpec& spec) {
  validate(spec.phases);
  require(spec.preCrackLength >= 0 && spec.preCrackLength < spec.grid.Lx, "pre-crack must be shorter than the plate");
  validate(spec.grid);
  const SpecimenSpec s = glassCeramicPreset(spec.grid, spec.preCrackLength);
  PointCloud cloud = specimenCloud(s, spec.grid);
  CrystalField field = spec.crystalField.empty() ? microstructureField(cloud, spec.crystalFraction, spec.seed)
                                                 : givenField(cloud, spec.crystalField);
  PointMaterial material = phaseMaterial(cloud, field.R, spec.phases);
  std::vector<double> G = material.G;
  b_ = buildFractureSpecimen(s, std::move(cloud), material, spec.linearSolver, spec.reuse, spec.zonePrecision);
  const double left = -0.5 * spec.grid.Lx;
  toughness_ = std::make_unique<CrackToughness>(*b_.fracture, left + spec.preCrackLength, 0.0, -left, std::move(G),
                                                std::move(field), spec.phases);
}

std::vector<double> GlassCeramicSpecimen::onDomain(int component) const {
  std::vector<double> v;
  for (std::size_t p : b_.disc->cloud.domain) v.push_back(b_.fracture->displacement()[2 * p + component]);
  return v;
}

std::vector<double> GlassCeramicSpecimen::damage() const {
  return damageField(b_.fracture->bonds(), b_.disc->cloud, b_.disc->neighbours);
}

std::vector<double> GlassCeramicSpecimen::youngsModulus() const {
  std::vector<double> v;
  for (std::size_t p : b_.disc->cloud.domain) v.push_back(b_.E[p]);
  return v;
}

double GlassCeramicSpecimen::reactionForce() const {
  return b_.fracture->collarForce(b_.collars[static_cast<std::size_t>(Side::Top)])[1];
}

}  // namespace peristep
