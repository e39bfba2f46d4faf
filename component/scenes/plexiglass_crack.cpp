#include "scenes/plexiglass_crack.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "geometry/point_cloud.hpp"

namespace peristep {

DynamicScene makePlexiglassCrack(const PlexiglassCrackSpec& s) {
  validateHorizon(s.meshRatio);
  require(s.horizon > 0 && s.side > 0 && s.crackLength > 0 && s.crackLength < s.side,
          "Plexiglass crack: a positive horizon and side and 0 < crack length < side are required");
  const double eps = s.horizon, L = s.side;
  const double h = eps / s.meshRatio;
  const double cellsAcross = L / h, collarCells = eps / h;
  require(std::abs(cellsAcross - std::round(cellsAcross)) < 1e-6 && std::abs(collarCells - std::round(collarCells)) < 1e-6,
          "Plexiglass crack: h = eps/(eps/h) must divide the side and the horizon (h = " + std::to_string(h) + " m)");
  const auto nx = static_cast<std::size_t>(std::llround(cellsAcross));
  const auto nc = static_cast<std::size_t>(std::llround(collarCells));

  DynamicScene scene;
  scene.nx = nx;
  scene.ny = nx + 2 * nc;
  scene.x0 = 0.5 * h;
  scene.y0 = -eps + 0.5 * h;
  scene.cloud = cellCentredLattice(scene.nx, scene.ny, h, scene.x0, scene.y0);
  const PointCloud& c = scene.cloud;
  const double xc = 0.5 * L, tol = 1e-9 * h;
  scene.cracks = {Segment{xc, -eps - h, xc, s.crackLength}};

  const StateBasedInput& in = s.material;
  StateBasedBondOptions bo;
  bo.horizon = eps;
  bo.cuts = scene.cracks;
  scene.model = std::make_unique<StateBasedModel>(makeStateBasedMaterial(in, eps), buildStateBasedBonds(c, bo));
  scene.problem = std::make_unique<DynamicProblem>(*scene.model, in.density);

  std::vector<std::uint32_t> top, left, right;
  scene.material.assign(c.size(), 0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    const auto dx = static_cast<std::uint32_t>(2 * p);
    if (c.y[p] > L)
      top.push_back(dx);
    else if (c.y[p] < 0)
      (c.x[p] <= xc + tol ? left : right).push_back(dx);  // the crack's left face takes nodes on its line
    else
      scene.material[p] = 1;
  }
  scene.problem->prescribeVelocity(top, 0.0);
  scene.problem->prescribeVelocity(left, -s.pullVelocity);
  scene.problem->prescribeVelocity(right, s.pullVelocity);
  scene.adjacent = findNeighbours(c, 1.5 * h);
  scene.timeStep = s.timeStep;
  scene.endTime = s.endTime;
  return scene;
}

}  // namespace peristep
