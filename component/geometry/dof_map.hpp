#pragma once
// Numbering of the unknowns of a point cloud: u (two components) and theta per point, as the LPS
// system 000:(3.1)-(3.2) uses them; the numbering itself is models/lps_system.hpp's numberDofs.
#include <cstdint>
#include <vector>

namespace peristep {

// Unknowns: u on the domain points, theta on the domain and on every collar point within delta of it;
// u on the rest of the collar is prescribed (000 Sec. 2.1). Numbered point by point (u_x, u_y, theta)
// so that the matrix keeps the locality of the cloud.
struct DofMap {
  std::vector<std::int64_t> u;      // per point: index of u_x (u_y follows), -1 where u is prescribed
  std::vector<std::int64_t> theta;  // per point: index of theta, -1 where theta is not needed
  std::int64_t size = 0;

  // 1 where theta is an unknown
  std::vector<char> thetaPoints() const {
    std::vector<char> t(theta.size());
    for (std::size_t p = 0; p < theta.size(); ++p) t[p] = theta[p] >= 0;
    return t;
  }

  // f(row) for the unknowns of point p, in their order.
  template <class F>
  void forEachRow(std::size_t p, F&& f) const {
    if (u[p] >= 0) {
      f(u[p]);
      f(u[p] + 1);
    }
    if (theta[p] >= 0) f(theta[p]);
  }
};

}  // namespace peristep
