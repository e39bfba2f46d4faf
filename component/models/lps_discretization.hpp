#pragma once
// What depends on the point cloud only: neighbours, quadrature weights, unknown numbering.
// Built once per geometry and shared by every sample and load step on it.
#include <vector>

#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"
#include "models/lps_system.hpp"

namespace peristep {

struct LpsDiscretization {
  PointCloud cloud;
  Neighbours neighbours;
  std::vector<double> weights;  // aligned with neighbours.index
  DofMap dofs;
  double neighbourSeconds = 0, weightSeconds = 0;

  static LpsDiscretization build(const GridSpec& spec);
};

}  // namespace peristep
