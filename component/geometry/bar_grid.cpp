#include "geometry/bar_grid.hpp"

#include "core/errors.hpp"

namespace peristep {

std::vector<double> barGrid(double length, int bonds, double jitter, ScatterStream& stream) {
  require(length > 0 && bonds >= 2, "bar grid: needs a positive length and at least 2 bonds");
  require(jitter >= 0 && jitter < 1, "bar grid: the spacing jitter must lie in [0, 1)");
  std::vector<double> x(static_cast<std::size_t>(bonds) + 1, 0.0);
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double spacing = jitter > 0 ? 1.0 + jitter * stream.sign() * stream.uniform() : 1.0;  // 002:(36) in units of h
    x[i] = x[i - 1] + spacing;
  }
  const double scale = length / x.back();
  for (double& xi : x) xi *= scale;
  x.back() = length;
  return x;
}

}  // namespace peristep
