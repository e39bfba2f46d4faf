#pragma once
// Exact mean and standard deviation, over the random coordinates, of the local solution u0(x; xi) of the
// verification scenes (000 Sec. 4: Tests 1-3). A sample study compares its moments 000:(3.10)-(3.11)
// with these; the difference falls with the number of collocation points down to the spatial error.
#include <optional>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "scenes/scene_model.hpp"

namespace peristep {

struct ExactMoments {
  std::vector<double> meanUx, meanUy, stdUx, stdUy;  // domain points, image order; for load factor 1
};

// None for scenes without an exact solution. Cost: (reference nodes) x (domain points) evaluations of u0.
std::optional<ExactMoments> exactMoments(const SceneParameters& p, const PointCloud& cloud);

}  // namespace peristep
