#pragma once
// A dynamic fracture scene of the state-based model: the lattice, the model and the equation of
// motion with its boundary conditions, plus what the fracture diagnostics need to know.
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

  double h() const { return cloud.h; }
  double horizon() const { return model->bonds().horizon; }
};

// Cell-centred nx x ny lattice of spacing h whose node (0, 0) sits at (x0, y0).
PointCloud cellCentredLattice(std::size_t nx, std::size_t ny, double h, double x0, double y0);

}  // namespace peristep
