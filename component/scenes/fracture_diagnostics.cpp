#include "scenes/fracture_diagnostics.hpp"

#include <algorithm>
#include <cmath>

#include "scenes/crack_zone.hpp"

namespace peristep {

FractureDiagnostics::FractureDiagnostics(DynamicScene& scene)
    : scene_(scene),
      Z_(scene.cloud.size(), 0.0),
      energyDensity_(scene.cloud.size(), 0.0),
      ZWithPreCrack_(scene.cloud.size(), 0.0),
      energyWithPreCrack_(scene.cloud.size(), 0.0) {}

std::vector<double> FractureDiagnostics::crackLengths(const std::vector<double>& Z) const {
  const PointCloud& c = scene_.cloud;
  const std::vector<int> owner = crackZoneOwners(scene_, Z);
  std::vector<double> lengths(scene_.cracks.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (owner[p] < 0) continue;
    double& l = lengths[static_cast<std::size_t>(owner[p])];
    l = std::max(l, crackCoordinates(scene_.cracks[static_cast<std::size_t>(owner[p])], c.x[p], c.y[p]).advance);
  }
  return lengths;
}

// Samples the segment every h/8 and counts the samples whose lattice cell belongs to D.
double FractureDiagnostics::lengthInMaterial(const Segment& s) const {
  const double h = scene_.h(), L = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  const auto samples = static_cast<std::size_t>(std::ceil(8.0 * L / h));
  std::size_t inside = 0;
  for (std::size_t k = 0; k < samples; ++k) {
    const double t = (static_cast<double>(k) + 0.5) / static_cast<double>(samples);
    const double i = std::round((s.x0 + t * (s.x1 - s.x0) - scene_.x0) / h);
    const double j = std::round((s.y0 + t * (s.y1 - s.y0) - scene_.y0) / h);
    if (i < 0 || j < 0 || i >= static_cast<double>(scene_.nx) || j >= static_cast<double>(scene_.ny)) continue;
    inside += scene_.material[static_cast<std::size_t>(j) * scene_.nx + static_cast<std::size_t>(i)] ? 1 : 0;
  }
  return L * static_cast<double>(inside) / static_cast<double>(samples);
}

EnergyRecord FractureDiagnostics::measure(const TimeIntegrator& integrator) {
  StateBasedModel& model = *scene_.model;
  const double* u = integrator.displacement();
  EnergyRecord r;
  r.time = integrator.time();
  r.kinetic = scene_.problem->kineticEnergy(integrator.velocity());
  r.elastic = model.energy(u);
  r.externalWork = integrator.externalWork();
  const double V = model.pointVolume(0);
  // 001 Sec. 6.1.1: P.E. is the tensile energy of the points of D with Z > 1.
  const auto crackZone = [&](const std::vector<double>& Z, const std::vector<double>& e, double& energy, double& maxZ) {
    for (std::size_t p = 0; p < Z.size(); ++p) {
      if (!scene_.material[p]) continue;
      maxZ = std::max(maxZ, Z[p]);
      if (Z[p] > 1.0) energy += V * e[p];
    }
  };
  model.damage(u, Z_.data());
  model.tensileEnergyDensity(u, energyDensity_.data());
  crackZone(Z_, energyDensity_, r.fractureEnergy, r.maxDamage);
  for (const double l : crackLengths(Z_)) r.crackLength += l;

  ZWithPreCrack_ = Z_;
  energyWithPreCrack_ = energyDensity_;
  model.raiseDamageByPreCrack(u, ZWithPreCrack_.data());
  model.addPreCrackEnergyDensity(energyWithPreCrack_.data());
  crackZone(ZWithPreCrack_, energyWithPreCrack_, r.fractureEnergyWithPreCrack, r.maxDamageWithPreCrack);
  const std::vector<double> grown = crackLengths(ZWithPreCrack_);
  for (std::size_t k = 0; k < grown.size(); ++k)
    r.crackLengthWithPreCrack += lengthInMaterial(scene_.cracks[k]) + grown[k];
  return r;
}

}  // namespace peristep
