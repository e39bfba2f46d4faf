#include "models/boundary_function.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace peristep {

std::vector<double> rectangleBoundaryFunction(const PointCloud& c, double x0, double x1, double y0, double y1,
                                              double layer) {
  require(x1 > x0 && y1 > y0, "boundary function: empty rectangle");
  require(std::isfinite(layer) && layer > 0, "boundary function: the boundary layer must be positive");
  std::vector<double> omega(c.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    const double d = std::min({c.x[p] - x0, x1 - c.x[p], c.y[p] - y0, y1 - c.y[p]});
    if (d <= 0) continue;
    const double s = std::min(d / layer, 1.0);
    omega[p] = s * s * (3.0 - 2.0 * s);
  }
  return omega;
}

}  // namespace peristep
