#include "scenes/fracture_diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace peristep {

FractureDiagnostics::FractureDiagnostics(DynamicScene& scene)
    : scene_(scene), Z_(scene.cloud.size(), 0.0), energyDensity_(scene.cloud.size(), 0.0) {}

std::vector<double> FractureDiagnostics::crackLengths() const {
  const PointCloud& c = scene_.cloud;
  const std::size_t n = c.size();
  const double eps = scene_.horizon();
  std::vector<int> owner(n, -1);
  std::deque<std::size_t> queue;
  const auto cracked = [&](std::size_t p) { return scene_.material[p] && Z_[p] > 1.0; };
  for (std::size_t k = 0; k < scene_.cracks.size(); ++k) {
    const Segment& s = scene_.cracks[k];
    for (std::size_t p = 0; p < n; ++p)
      if (owner[p] < 0 && cracked(p) && std::hypot(c.x[p] - s.x1, c.y[p] - s.y1) <= eps) {
        owner[p] = static_cast<int>(k);
        queue.push_back(p);
      }
  }
  while (!queue.empty()) {  // multi-source BFS: each Z > 1 point goes to the nearest crack zone
    const std::size_t p = queue.front();
    queue.pop_front();
    for (std::size_t k = scene_.adjacent.begin(p); k < scene_.adjacent.end(p); ++k) {
      const std::size_t q = scene_.adjacent.index[k];
      if (owner[q] < 0 && cracked(q)) {
        owner[q] = owner[p];
        queue.push_back(q);
      }
    }
  }
  std::vector<double> lengths(scene_.cracks.size(), 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    if (owner[p] < 0) continue;
    const Segment& s = scene_.cracks[static_cast<std::size_t>(owner[p])];
    const double L = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
    const double advance = ((c.x[p] - s.x1) * (s.x1 - s.x0) + (c.y[p] - s.y1) * (s.y1 - s.y0)) / L;
    double& l = lengths[static_cast<std::size_t>(owner[p])];
    l = std::max(l, advance);
  }
  return lengths;
}

EnergyRecord FractureDiagnostics::measure(const TimeIntegrator& integrator) {
  StateBasedModel& model = *scene_.model;
  const double* u = integrator.displacement();
  EnergyRecord r;
  r.time = integrator.time();
  r.kinetic = scene_.problem->kineticEnergy(integrator.velocity());
  r.elastic = model.energy(u);
  r.externalWork = integrator.externalWork();
  model.damage(u, Z_.data());
  model.tensileEnergyDensity(u, energyDensity_.data());
  const double V = model.pointVolume(0);
  for (std::size_t p = 0; p < Z_.size(); ++p) {
    if (!scene_.material[p]) continue;
    r.maxDamage = std::max(r.maxDamage, Z_[p]);
    if (Z_[p] > 1.0) r.fractureEnergy += V * energyDensity_[p];  // 001 Sec. 6.1.1, P.E.
  }
  for (const double l : crackLengths()) r.crackLength += l;
  return r;
}

}  // namespace peristep
