#pragma once
// A dynamic fracture scene of the state-based model: the lattice, the model and the equation of
// motion with its boundary conditions, plus what the fracture diagnostics need to know.
#include <array>
#include <memory>
#include <vector>

#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"
#include "geometry/segments.hpp"
#include "models/state_based_model.hpp"
#include "solvers/dynamic_problem.hpp"

namespace peristep {

struct DynamicScene {
  PointCloud cloud;                         // cell-centred lattice (collars included)
  std::size_t nx = 0, ny = 0;               // lattice size, row-major
  double x0 = 0, y0 = 0;                    // coordinates of node (0, 0)
  std::vector<char> material;               // 1 on the material domain D (diagnostics), 0 on collars
  std::vector<Segment> cracks;              // pre-cracks; each grows from its (x1, y1) end
  std::unique_ptr<StateBasedModel> model;   // owned here so that problem's reference stays valid
  std::unique_ptr<DynamicProblem> problem;
  Neighbours adjacent;                      // lattice neighbours within 1.5 h: crack-zone connectivity
  double timeStep = 0, endTime = 0;         // the paper's choices for this scene
  // The specimen's own (empty for the papers' scenes): the points written to the [ny][nx] image outputs,
  // Void ones included (empty: the material nodes in lattice order); Young's modulus per point (empty:
  // 3 K (1 - 2 nu) everywhere); the collar points of each held side, by Side.
  std::vector<std::size_t> outputPoints;
  std::vector<double> youngsModulus;
  std::array<std::vector<std::size_t>, 4> grips;

  double h() const { return cloud.h; }
  double horizon() const { return model->bonds().horizon; }
};

struct SceneParameters;
// The importer's specimen (SceneId::Specimen) with SpecimenModel::Dynamic: its cloud, Void and pre-cracks,
// the state-based material of p (bulkModulus, poissonRatio, criticalEnergyReleaseRate) with the stiffness
// factor E/(3 K (1 - 2 nu)) of each point's materialYoungsModulus (times the KL factor) and its
// materialDensity, and each held grip's collar moving at loadFactor * (vx, vy). Time step: 0.8 of the estimated stability limit of
// central difference (solvers/stability_limit.hpp).
DynamicScene makeDynamicSpecimen(const SceneParameters& p);
// The material of 001 Table 1 as the parameters set it (bulkModulus, poissonRatio,
// criticalEnergyReleaseRate, density).
StateBasedInput dynamicMaterial(const SceneParameters& p);

// Cell-centred nx x ny lattice of spacing h whose node (0, 0) sits at (x0, y0).
PointCloud cellCentredLattice(std::size_t nx, std::size_t ny, double h, double x0, double y0);

}  // namespace peristep
