#include "scenes/stiff_inclusions.hpp"

#include <cmath>
#include <numbers>

#include "core/errors.hpp"

namespace peristep {

DynamicScene makeStiffInclusions(const StiffInclusionsSpec& s) {
  validateHorizon(s.meshRatio);
  require(s.contrast >= 1 && std::isfinite(s.contrast), "stiff inclusions: contrast must be >= 1");
  require(s.rampTime > 0 && s.endTime > 0, "stiff inclusions: ramp and end times must be positive");
  DynamicScene scene;
  scene.nx = s.nx;
  scene.ny = s.ny;
  scene.x0 = scene.y0 = 0.5 * s.h;
  scene.cloud = cellCentredLattice(s.nx, s.ny, s.h, scene.x0, scene.y0);
  const PointCloud& c = scene.cloud;
  const double Lx = static_cast<double>(s.nx) * s.h, Ly = static_cast<double>(s.ny) * s.h, eps = s.meshRatio * s.h;

  std::vector<double> kappa(c.size(), 1.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      const double cx = Lx * (i + 1) / 4.0, cy = Ly * (j + 1) / 3.0;
      for (std::size_t p = 0; p < c.size(); ++p)
        if (std::hypot(c.x[p] - cx, c.y[p] - cy) <= s.inclusionRadius) kappa[p] = s.contrast;
    }
  StateBasedInput in;
  StateBasedBondOptions bo;
  bo.horizon = eps;
  bo.stiffness = kappa;
  scene.model = std::make_unique<StateBasedModel>(makeStateBasedMaterial(in, eps), buildStateBasedBonds(c, bo));
  scene.problem = std::make_unique<DynamicProblem>(*scene.model, in.density);

  std::vector<std::uint32_t> clamped;
  std::vector<double> profile(2 * c.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (c.x[p] < eps) {
      clamped.push_back(static_cast<std::uint32_t>(2 * p));
      clamped.push_back(static_cast<std::uint32_t>(2 * p + 1));
    }
    if (c.x[p] > Lx - eps) profile[2 * p] = s.load;
  }
  scene.problem->prescribeVelocity(clamped, 0.0);
  const double tr = s.rampTime;
  scene.problem->setBodyForce(std::move(profile), [tr](double t) {
    if (t >= tr) return 1.0;
    const double r = std::sin(0.5 * std::numbers::pi * t / tr);
    return r * r;
  });
  scene.material.assign(c.size(), 1);
  scene.adjacent = findNeighbours(c, 1.5 * s.h);
  scene.endTime = s.endTime;
  return scene;
}

}  // namespace peristep
