#pragma once
// The boundary function omega of 001 Sec. 2: 1 in the interior, decaying smoothly to 0 on the
// boundary of the material domain. It makes the evolution well posed in 001's analysis; the
// simulations of 001 Sec. 6 use omega = 1 (no boundary layer), which is the default everywhere.
#include <vector>

#include "geometry/point_cloud.hpp"

namespace peristep {

// omega for the rectangle [x0, x1] x [y0, y1]: with d the distance of a point to the rectangle's
// boundary and s = min(d/layer, 1), omega = s^2 (3 - 2 s) (C^1, Lipschitz); 0 outside the rectangle.
std::vector<double> rectangleBoundaryFunction(const PointCloud& cloud, double x0, double x1, double y0, double y1,
                                              double layer);

}  // namespace peristep
