#include "scenes/dynamic_scene.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep {

PointCloud cellCentredLattice(std::size_t nx, std::size_t ny, double h, double x0, double y0) {
  require(nx >= 2 && ny >= 2, "lattice: at least 2 x 2 nodes are needed");
  require(std::isfinite(h) && h > 0, "lattice: the spacing must be positive");
  GridSpec g;
  g.nx = nx;
  g.ny = ny;
  g.Lx = static_cast<double>(nx - 1) * h;
  g.Ly = static_cast<double>(ny - 1) * h;
  g.collar = false;
  PointCloud c = makeRectangle(g);  // centred at the origin; shift node (0, 0) to (x0, y0)
  const double dx = x0 + 0.5 * g.Lx, dy = y0 + 0.5 * g.Ly;
  for (std::size_t p = 0; p < c.size(); ++p) {
    c.x[p] += dx;
    c.y[p] += dy;
  }
  c.h = h;
  return c;
}

}  // namespace peristep
