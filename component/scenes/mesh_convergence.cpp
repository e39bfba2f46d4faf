#include "scenes/mesh_convergence.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep {

double nestedL2Difference(const DynamicScene& coarse, const double* uc, const DynamicScene& fine, const double* uf) {
  const double hc = coarse.h(), hf = fine.h();
  const double ratio = hc / hf;
  require(std::abs(ratio - std::round(ratio)) < 1e-9 && ratio >= 1,
          "nested L2 difference: the coarse spacing must be an integer multiple of the fine one");
  // Lower-left corner of the coarse cell (0, 0).
  const double cx0 = coarse.x0 - 0.5 * hc, cy0 = coarse.y0 - 0.5 * hc;
  double sum = 0;
  const PointCloud& f = fine.cloud;
  for (std::size_t p = 0; p < f.size(); ++p) {
    if (!fine.material[p]) continue;
    const auto ix = static_cast<long>(std::floor((f.x[p] - cx0) / hc)), iy = static_cast<long>(std::floor((f.y[p] - cy0) / hc));
    require(ix >= 0 && iy >= 0 && ix < static_cast<long>(coarse.nx) && iy < static_cast<long>(coarse.ny),
            "nested L2 difference: the lattices do not cover the same domain");
    const std::size_t q = static_cast<std::size_t>(iy) * coarse.nx + static_cast<std::size_t>(ix);
    const double dx = uc[2 * q] - uf[2 * p], dy = uc[2 * q + 1] - uf[2 * p + 1];
    sum += dx * dx + dy * dy;
  }
  return std::sqrt(sum * hf * hf);
}

double rateEstimate(double d12, double d23, double ratio) {
  require(d12 > 0 && d23 > 0 && ratio > 1, "rate estimate: differences must be positive and the mesh ratio above 1");
  return (std::log(d12) - std::log(d23)) / std::log(ratio);
}

}  // namespace peristep
