// A specimen under the state-based model of 001: the cloud, Void and pre-cracks of the quasi-static
// specimen (scenes/specimen.hpp), so both models see the same points.
#include <algorithm>
#include <cmath>
#include <string>

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
  scene.grips.resize(4 + s.boxes.size());
  for (std::size_t k = 0; k < scene.grips.size(); ++k) {
    const HeldComponents held = k < 4 ? s.grips[k].components : s.boxes[k - 4].components;
    scene.grips[k].x = held != HeldComponents::Y;
    scene.grips[k].y = held != HeldComponents::X;
  }
  std::vector<double> density(c.size()), body;
  const bool bodyForce = !s.bodyForceRateX.empty() || !s.bodyForceRateY.empty();
  if (bodyForce) body.assign(2 * c.size(), 0.0);
  for (std::size_t q = 0; q < c.size(); ++q) {
    const ImageSource src = imageSource(c, q);
    density[q] = s.density[src.image];
    if (c.image[q] >= 0) scene.outputPoints[static_cast<std::size_t>(c.image[q])] = q;
    if (c.isVoid(q)) continue;
    scene.youngsModulus[q] = s.youngsModulus[src.image] * factor[q];
    bo.stiffness[q] = scene.youngsModulus[q] / E0;
    if (c.inDomain(q)) scene.material[q] = 1;
    if (const int grip = gripOf(s, c, q); grip >= 0) scene.grips[static_cast<std::size_t>(grip)].points.push_back(q);
    if (bodyForce && c.inDomain(q)) {  // on the material only: a collar's motion is prescribed
      if (!s.bodyForceRateX.empty()) body[2 * q] = s.bodyForceRateX[src.image];
      if (!s.bodyForceRateY.empty()) body[2 * q + 1] = s.bodyForceRateY[src.image];
    }
  }
  for (std::size_t b = 0; b < s.boxes.size(); ++b)
    require(!scene.grips[4 + b].points.empty(),
            "grip box " + std::to_string(b) + " holds no material point of the specimen (a box outside the plate "
            "and its collar, or on Void)");
  scene.model = std::make_unique<StateBasedModel>(makeStateBasedMaterial(in, c.delta), buildStateBasedBonds(c, bo));
  // A uniform map keeps one density (and the integrators' unscaled path).
  const bool uniform = std::all_of(density.begin(), density.end(), [&](double r) { return r == density.front(); });
  scene.problem = std::make_unique<DynamicProblem>(*scene.model, density.front());
  if (!uniform) scene.problem->setDensity(std::move(density));
  for (std::size_t k = 0; k < scene.grips.size(); ++k) {
    const DynamicScene::HeldPoints& grip = scene.grips[k];
    const double vx = k < 4 ? s.grips[k].vx : s.boxes[k - 4].vx, vy = k < 4 ? s.grips[k].vy : s.boxes[k - 4].vy;
    std::vector<std::uint32_t> x, y;
    for (std::size_t q : grip.points) {
      if (grip.x) x.push_back(static_cast<std::uint32_t>(2 * q));
      if (grip.y) y.push_back(static_cast<std::uint32_t>(2 * q + 1));
    }
    if (!x.empty()) scene.problem->prescribeVelocity(x, vx);
    if (!y.empty()) scene.problem->prescribeVelocity(y, vy);
  }
  if (bodyForce) scene.problem->setBodyForce(std::move(body), [](double t) { return t; });
  scene.adjacent = findNeighbours(c, 1.5 * c.h);
  // The papers' scenes come with their step; a specimen's is set by its own stiffness and spacing.
  if (p.internalTimeStep == 0) scene.timeStep = 0.8 * estimateStabilityLimit(*scene.problem).criticalStep;
  return scene;
}

void assignUniformMaterial(SpecimenSpec& s, std::size_t points, const StateBasedInput& m) {
  s.youngsModulus.assign(points, 3.0 * m.bulkModulus * (1.0 - 2.0 * m.poissonRatio));
  s.poissonRatio.assign(points, m.poissonRatio);
  s.fractureEnergy.assign(points, m.fractureEnergy);
  s.density.assign(points, m.density);
}

DynamicScene makeDynamicPreset(const GridSpec& grid, const StateBasedInput& material, SpecimenSpec preset,
                               double timeStep, double endTime) {
  SceneParameters p;
  p.scene = SceneId::Specimen;
  p.grid = grid;
  p.poissonRatio = material.poissonRatio;
  p.bulkModulus = material.bulkModulus;
  p.criticalEnergyReleaseRate = material.fractureEnergy;
  p.density = material.density;
  p.internalTimeStep = timeStep;
  p.specimen = std::move(preset);
  validate(p);
  DynamicScene scene = makeDynamicSpecimen(p);
  scene.timeStep = timeStep;
  scene.endTime = endTime;
  return scene;
}

}  // namespace peristep
