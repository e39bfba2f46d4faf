#pragma once
// Neighbour lists within the horizon, stored as CSR ("bonds").
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace peristep {

// Row p lists the points j != p with |x_j - x_p| <= radius, in ascending order.
struct Neighbours {
  std::vector<std::size_t> offset;   // size points + 1
  std::vector<std::uint32_t> index;  // size bonds

  std::size_t points() const { return offset.size() - 1; }
  std::size_t bonds() const { return index.size(); }
  std::size_t begin(std::size_t p) const { return offset[p]; }
  std::size_t end(std::size_t p) const { return offset[p + 1]; }
  // The point whose row holds bond position k (bisection of the row offsets).
  std::size_t owner(std::size_t k) const {
    return static_cast<std::size_t>(std::upper_bound(offset.begin(), offset.end(), k) - offset.begin() - 1);
  }
};

// Cell-list search in O(points * neighbours). Points at exactly the radius are included (up to a
// relative round-off tolerance), so a lattice gets the symmetric stencil it should.
Neighbours findNeighbours(const PointCloud& cloud, double radius);

}  // namespace peristep
