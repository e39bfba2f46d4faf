// The importer's specimen under the state-based model of 001: the cloud, Void and pre-cracks of the
// quasi-static specimen (scenes/specimen.hpp), so both models see the same points.
#include <cmath>

#include "core/errors.hpp"
#include "models/state_based_material.hpp"
#include "scenes/dynamic_scene.hpp"
#include "scenes/kl_material.hpp"
#include "scenes/scene_model.hpp"
#include "solvers/stability_limit.hpp"

namespace peristep {

DynamicScene makeDynamicSpecimen(const SceneParameters& p) {
  const SpecimenSpec& s = p.specimen;
  DynamicScene scene;
  scene.cloud = specimenCloud(s, p.grid);
  const PointCloud& c = scene.cloud;
  scene.nx = c.nx + 2 * c.layers;
  scene.ny = c.ny + 2 * c.layers;
  scene.x0 = c.x.front();
  scene.y0 = c.y.front();
  scene.cracks = s.cracks;

  const StateBasedInput in = dynamicMaterial(p);
  const double E0 = 3.0 * in.bulkModulus * (1.0 - 2.0 * in.poissonRatio);  // 001 Table 1's relation
  std::vector<double> factor(c.size(), 1.0);
  if (s.material == SpecimenMaterial::KlField) factor = klMaterial(*sharedKlField(c, p), 1.0, p);
  StateBasedBondOptions bo;
  bo.horizon = c.delta;
  bo.cuts = scene.cracks;
  bo.stiffness.assign(c.size(), 1.0);
  scene.material.assign(c.size(), 0);
  scene.youngsModulus.assign(c.size(), 0.0);
  scene.outputPoints.assign(c.nx * c.ny, 0);
  std::vector<double> density(c.size());
  for (std::size_t q = 0; q < c.size(); ++q) {
    const ImageSource src = imageSource(c, q);
    density[q] = s.density[src.image];
    if (c.image[q] >= 0) scene.outputPoints[static_cast<std::size_t>(c.image[q])] = q;
    if (c.isVoid(q)) continue;
    scene.youngsModulus[q] = s.youngsModulus[src.image] * factor[q];
    bo.stiffness[q] = scene.youngsModulus[q] / E0;
    if (c.inDomain(q)) scene.material[q] = 1;
    else scene.grips[static_cast<std::size_t>(src.side)].push_back(q);
  }
  scene.model = std::make_unique<StateBasedModel>(makeStateBasedMaterial(in, c.delta), buildStateBasedBonds(c, bo));
  scene.problem = std::make_unique<DynamicProblem>(*scene.model, in.density);
  scene.problem->setDensity(std::move(density));
  for (std::size_t k = 0; k < 4; ++k) {
    if (scene.grips[k].empty()) continue;
    std::vector<std::uint32_t> x, y;
    for (std::size_t q : scene.grips[k]) {
      x.push_back(static_cast<std::uint32_t>(2 * q));
      y.push_back(static_cast<std::uint32_t>(2 * q + 1));
    }
    scene.problem->prescribeVelocity(x, s.grips[k].vx);
    scene.problem->prescribeVelocity(y, s.grips[k].vy);
  }
  scene.adjacent = findNeighbours(c, 1.5 * c.h);
  // The papers' scenes come with their step; a specimen's is set by its own stiffness and spacing.
  if (p.internalTimeStep == 0) scene.timeStep = 0.8 * estimateStabilityLimit(*scene.problem).criticalStep;
  return scene;
}

}  // namespace peristep
