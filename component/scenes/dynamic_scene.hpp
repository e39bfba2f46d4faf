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
  PointCloud cloud;                         // square lattice, collars included
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
  // 3 K (1 - 2 nu) everywhere); the points each grip holds and in which components: the sides' collars by
  // Side, then the grip boxes.
  struct HeldPoints {
    std::vector<std::size_t> points;
    bool x = true, y = true;
  };
  std::vector<std::size_t> outputPoints;
  std::vector<double> youngsModulus;
  std::vector<HeldPoints> grips;

  double h() const { return cloud.h; }
  double horizon() const { return model->bonds().horizon; }
};

struct SceneParameters;
struct SpecimenSpec;
// A specimen with SpecimenModel::Dynamic (the importer's, or the preset of scenes 5-7): its cloud, Void and
// pre-cracks, the state-based material of p (bulkModulus, poissonRatio, criticalEnergyReleaseRate) with the
// stiffness factor E/(3 K (1 - 2 nu)) of each point's materialYoungsModulus (times the KL factor) and its
// materialDensity, each grip's points moving at loadFactor * (vx, vy) in its held components, and the body
// force loadFactor * t * bodyForceRate. Time step: p.internalTimeStep, or 0 for 0.8 of the estimated
// stability limit of central difference (solvers/stability_limit.hpp).
DynamicScene makeDynamicSpecimen(const SceneParameters& p);
// A dynamic preset (scenes 5-7) built for a bench or test without the FMU: maps of one material (E = 3 K
// (1 - 2 nu), 001 Table 1's relation, so the stiffness factor is 1), and the scene of a preset's grips and
// loads on `grid` with that material and the paper's time step and end time.
void assignUniformMaterial(SpecimenSpec& s, std::size_t points, const StateBasedInput& material);
DynamicScene makeDynamicPreset(const GridSpec& grid, const StateBasedInput& material, SpecimenSpec preset,
                               double timeStep, double endTime);
// The material of 001 Table 1 as the parameters set it (bulkModulus, poissonRatio,
// criticalEnergyReleaseRate, density).
StateBasedInput dynamicMaterial(const SceneParameters& p);

// Cell-centred nx x ny lattice of spacing h whose node (0, 0) sits at (x0, y0).
PointCloud cellCentredLattice(std::size_t nx, std::size_t ny, double h, double x0, double y0);

}  // namespace peristep
