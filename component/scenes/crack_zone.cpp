#include "scenes/crack_zone.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>

namespace peristep {

CrackCoordinates crackCoordinates(const Segment& s, double x, double y) {
  const double L = std::hypot(s.x1 - s.x0, s.y1 - s.y0), dx = (s.x1 - s.x0) / L, dy = (s.y1 - s.y0) / L;
  const double rx = x - s.x1, ry = y - s.y1;
  return {rx * dx + ry * dy, dx * ry - dy * rx};
}

std::vector<int> crackZoneOwners(const DynamicScene& scene, const std::vector<double>& Z) {
  const PointCloud& c = scene.cloud;
  const std::size_t n = c.size();
  const double eps = scene.horizon();
  std::vector<int> owner(n, -1);
  std::deque<std::size_t> queue;
  const auto cracked = [&](std::size_t p) { return scene.material[p] && Z[p] > 1.0; };
  for (std::size_t k = 0; k < scene.cracks.size(); ++k) {
    const Segment& s = scene.cracks[k];
    for (std::size_t p = 0; p < n; ++p)
      if (owner[p] < 0 && cracked(p) && std::hypot(c.x[p] - s.x1, c.y[p] - s.y1) <= eps) {
        owner[p] = static_cast<int>(k);
        queue.push_back(p);
      }
  }
  while (!queue.empty()) {  // multi-source search: each Z > 1 point goes to the nearest crack zone
    const std::size_t p = queue.front();
    queue.pop_front();
    for (std::size_t k = scene.adjacent.begin(p); k < scene.adjacent.end(p); ++k) {
      const std::size_t q = scene.adjacent.index[k];
      if (owner[q] < 0 && cracked(q)) {
        owner[q] = owner[p];
        queue.push_back(q);
      }
    }
  }
  return owner;
}

std::vector<std::vector<CrackBandRow>> crackBands(const DynamicScene& scene, const std::vector<double>& Z) {
  const PointCloud& c = scene.cloud;
  const double h = scene.h();
  const std::vector<int> owner = crackZoneOwners(scene, Z);
  std::vector<std::vector<std::pair<double, double>>> points(scene.cracks.size());  // (advance, offset)
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (owner[p] < 0) continue;
    const auto [advance, offset] = crackCoordinates(scene.cracks[static_cast<std::size_t>(owner[p])], c.x[p], c.y[p]);
    if (advance > 1e-9 * h) points[static_cast<std::size_t>(owner[p])].emplace_back(advance, offset);  // not the tip's row
  }
  // Rows: points sorted by advance, a new row wherever the advance moves on by more than h/2 (a lattice
  // row along the crack shares one advance up to rounding; rounding advance / h would split or merge rows
  // that sit half a cell from the tip).
  std::vector<std::vector<CrackBandRow>> bands(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    std::sort(points[k].begin(), points[k].end());
    for (const auto& [advance, offset] : points[k]) {
      if (bands[k].empty() || advance > bands[k].back().advance + 0.5 * h)
        bands[k].push_back(CrackBandRow{advance, offset, offset, 0});
      CrackBandRow& r = bands[k].back();
      r.left = std::min(r.left, offset), r.right = std::max(r.right, offset);
      ++r.points;
    }
  }
  return bands;
}

}  // namespace peristep
