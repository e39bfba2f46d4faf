#pragma once
// What depends on the point cloud only: neighbours, quadrature weights, unknown numbering.
// Built once per geometry and shared by every sample and load step on it.
#include <memory>
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

// The discretization of `spec`, built on the first request and handed out again for the same cloud, so
// that a sample loop (one component instance reset between samples) builds geometry, neighbours and
// weights once per study. Keeps the two most recently used clouds; thread-safe.
std::shared_ptr<const LpsDiscretization> sharedDiscretization(const GridSpec& spec);

}  // namespace peristep
