#include "scenes/bending_test.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "geometry/point_cloud.hpp"

namespace peristep {

DynamicScene makeBendingTest(const BendingSpec& s) {
  require(s.cracks == 1 || s.cracks == 2, "bending test: 1 or 2 pre-cracks (got " + std::to_string(s.cracks) + ")");
  validateHorizon(s.meshRatio);
  require(s.horizon > 0 && s.length > 0 && s.depth > 0 && s.crackLength > 0 && s.crackLength < s.depth,
          "bending test: positive sizes and a pre-crack shorter than the depth are required");
  const double eps = s.horizon, h = eps / s.meshRatio;
  const double cx = s.length / h, cy = s.depth / h;
  require(std::abs(cx - std::round(cx)) < 1e-6 && std::abs(cy - std::round(cy)) < 1e-6,
          "bending test: h = " + std::to_string(h) + " m must divide the beam's length and depth");

  DynamicScene scene;
  scene.nx = static_cast<std::size_t>(std::llround(cx));
  scene.ny = static_cast<std::size_t>(std::llround(cy));
  scene.x0 = scene.y0 = 0.5 * h;
  scene.cloud = cellCentredLattice(scene.nx, scene.ny, h, scene.x0, scene.y0);
  const PointCloud& c = scene.cloud;
  const double mid = 0.5 * s.length;
  for (const double x : s.cracks == 1 ? std::vector<double>{mid} : std::vector<double>{mid - s.crackOffset, mid + s.crackOffset})
    scene.cracks.push_back(Segment{x, -h, x, s.crackLength});

  const StateBasedInput& in = s.material;
  StateBasedBondOptions bo;
  bo.horizon = eps;
  bo.cuts = scene.cracks;
  scene.model = std::make_unique<StateBasedModel>(makeStateBasedMaterial(in, eps), buildStateBasedBonds(c, bo));
  scene.problem = std::make_unique<DynamicProblem>(*scene.model, in.density);

  require(s.loadDepth > 0 && s.loadDepth < s.depth, "bending test: the load band must lie inside the beam");
  // Rows of nodes carrying the load: those whose cells lie within the band, at least the top row.
  const double rows = std::max(1.0, std::floor(s.loadDepth / h + 1e-9));
  const double bandScale = s.loadDepth / (rows * h);
  std::vector<std::uint32_t> supports;
  std::vector<double> profile(2 * c.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    const bool bottom = c.y[p] < eps, top = c.y[p] > s.depth - rows * h;
    const double dl = std::abs(c.x[p] - s.supportCentre), dr = std::abs(c.x[p] - (s.length - s.supportCentre));
    if (bottom && (dl <= s.supportHalfWidth || dr <= s.supportHalfWidth)) supports.push_back(static_cast<std::uint32_t>(2 * p + 1));
    const double dm = std::abs(c.x[p] - mid);
    if (top && dm <= s.loadHalfWidth) profile[2 * p + 1] = bandScale * s.loadRate * (1.0 - dm / s.loadHalfWidth);
  }
  scene.material.assign(c.size(), 1);
  scene.problem->prescribeVelocity(supports, 0.0);
  scene.problem->setBodyForce(std::move(profile), [](double t) { return t; });
  scene.adjacent = findNeighbours(c, 1.5 * h);
  scene.timeStep = s.timeStep;
  scene.endTime = s.endTime;
  return scene;
}

}  // namespace peristep
