#include "geometry/neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace peristep {
namespace {

// Points binned into square cells of side >= radius, so each search looks at 3 x 3 cells.
struct CellList {
  double x0 = 0, y0 = 0, side = 1;
  std::size_t cx = 1, cy = 1;
  std::vector<std::size_t> start;   // size cells + 1
  std::vector<std::uint32_t> items; // point ids, grouped by cell

  std::size_t cellOf(double x, double y) const {
    const auto clampTo = [](double v, std::size_t n) {
      return static_cast<std::size_t>(std::clamp(v, 0.0, static_cast<double>(n - 1)));
    };
    return clampTo((y - y0) / side, cy) * cx + clampTo((x - x0) / side, cx);
  }
};

CellList binPoints(const PointCloud& c, double radius) {
  CellList cl;
  const auto [xmin, xmax] = std::minmax_element(c.x.begin(), c.x.end());
  const auto [ymin, ymax] = std::minmax_element(c.y.begin(), c.y.end());
  cl.x0 = *xmin;
  cl.y0 = *ymin;
  cl.side = radius * (1.0 + 1e-9);  // a point at exactly the radius must not fall two cells away
  cl.cx = static_cast<std::size_t>((*xmax - *xmin) / radius) + 1;
  cl.cy = static_cast<std::size_t>((*ymax - *ymin) / radius) + 1;
  std::vector<std::size_t> count(cl.cx * cl.cy + 1, 0);
  std::vector<std::size_t> cellOfPoint(c.size());
  for (std::size_t p = 0; p < c.size(); ++p) {
    cellOfPoint[p] = cl.cellOf(c.x[p], c.y[p]);
    ++count[cellOfPoint[p] + 1];
  }
  for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
  cl.start = count;
  cl.items.resize(c.size());
  for (std::size_t p = 0; p < c.size(); ++p) cl.items[count[cellOfPoint[p]]++] = static_cast<std::uint32_t>(p);
  return cl;
}

template <class Visit>
void forEachNeighbour(const PointCloud& c, const CellList& cl, double r2, std::size_t p, Visit&& visit) {
  const std::size_t cell = cl.cellOf(c.x[p], c.y[p]);
  const std::size_t ci = cell % cl.cx, cj = cell / cl.cx;
  for (std::size_t j = (cj > 0 ? cj - 1 : 0); j <= std::min(cj + 1, cl.cy - 1); ++j)
    for (std::size_t i = (ci > 0 ? ci - 1 : 0); i <= std::min(ci + 1, cl.cx - 1); ++i)
      for (std::size_t k = cl.start[j * cl.cx + i]; k < cl.start[j * cl.cx + i + 1]; ++k) {
        const std::uint32_t q = cl.items[k];
        const double dx = c.x[q] - c.x[p], dy = c.y[q] - c.y[p];
        if (q != p && dx * dx + dy * dy <= r2) visit(q);
      }
}

}  // namespace

Neighbours findNeighbours(const PointCloud& c, double radius) {
  require(radius > 0 && std::isfinite(radius), "neighbour radius must be positive");
  require(c.size() < std::numeric_limits<std::uint32_t>::max(), "too many points for 32-bit bond indices");
  const CellList cl = binPoints(c, radius);
  const double r2 = radius * radius * (1.0 + 1e-10);
  const auto n = static_cast<std::ptrdiff_t>(c.size());

  Neighbours nb;
  nb.offset.assign(c.size() + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    std::size_t count = 0;
    forEachNeighbour(c, cl, r2, static_cast<std::size_t>(p), [&](std::uint32_t) { ++count; });
    nb.offset[static_cast<std::size_t>(p) + 1] = count;
  }
  for (std::size_t p = 0; p < c.size(); ++p) nb.offset[p + 1] += nb.offset[p];
  nb.index.resize(nb.offset.back());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    std::size_t k = nb.offset[static_cast<std::size_t>(p)];
    forEachNeighbour(c, cl, r2, static_cast<std::size_t>(p), [&](std::uint32_t q) { nb.index[k++] = q; });
    std::sort(nb.index.begin() + static_cast<std::ptrdiff_t>(nb.offset[static_cast<std::size_t>(p)]),
              nb.index.begin() + static_cast<std::ptrdiff_t>(k));
  }
  return nb;
}

}  // namespace peristep
