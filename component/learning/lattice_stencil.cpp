#include "learning/lattice_stencil.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/errors.hpp"
#include "geometry/neighbours.hpp"
#include "quadrature/optimization_weights.hpp"

namespace peristep::learning {

int LatticeStencil::reach() const {
  int n = 0;
  for (std::size_t s = 0; s < size(); ++s) n = std::max({n, std::abs(di[s]), std::abs(dj[s])});
  return n;
}

LatticeStencil makeLatticeStencil(double hx, double hy, double delta) {
  require(hx > 0 && hy > 0 && delta > std::max(hx, hy), "lattice stencil: need hx, hy > 0 and delta > h");
  // A patch just large enough for the centre's neighbourhood; its weights are those of every lattice point.
  const int nxh = static_cast<int>(std::ceil(delta / hx)) + 1, nyh = static_cast<int>(std::ceil(delta / hy)) + 1;
  PointCloud cloud;
  cloud.h = std::min(hx, hy);
  cloud.delta = delta;
  for (int j = -nyh; j <= nyh; ++j)
    for (int i = -nxh; i <= nxh; ++i) {
      cloud.x.push_back(i * hx);
      cloud.y.push_back(j * hy);
    }
  cloud.region.assign(cloud.size(), Region::Domain);
  const std::size_t centre = cloud.size() / 2;
  const Neighbours nb = findNeighbours(cloud, delta);
  std::vector<char> active(cloud.size(), 0);
  active[centre] = 1;
  const std::vector<double> w = optimizationWeights(cloud, nb, active);
  LatticeStencil s;
  s.hx = hx, s.hy = hy, s.delta = delta;
  for (std::size_t k = nb.begin(centre); k < nb.end(centre); ++k) {
    const std::size_t q = nb.index[k];
    s.zx.push_back(cloud.x[q]);
    s.zy.push_back(cloud.y[q]);
    s.di.push_back(static_cast<int>(std::lround(cloud.x[q] / hx)));
    s.dj.push_back(static_cast<int>(std::lround(cloud.y[q] / hy)));
    s.r.push_back(std::hypot(cloud.x[q], cloud.y[q]));
    s.W.push_back(w[k]);
  }
  for (std::size_t a = 0; a < s.size(); ++a)
    for (std::size_t b = 0; b < s.size(); ++b)
      if (s.di[b] == -s.di[a] && s.dj[b] == -s.dj[a]) s.opposite.push_back(b);
  require(s.opposite.size() == s.size(), "lattice stencil: the neighbourhood is not symmetric");
  // Pairs share one weight (the minimum-norm weights are symmetric up to round-off).
  for (std::size_t a = 0; a < s.size(); ++a) s.W[a] = s.W[s.opposite[a]] = 0.5 * (s.W[a] + s.W[s.opposite[a]]);
  return s;
}

std::size_t PeriodicLattice::neighbour(std::size_t p, int di, int dj) const {
  const auto wrap = [](std::ptrdiff_t i, std::size_t n) {
    const auto m = static_cast<std::ptrdiff_t>(n);
    return static_cast<std::size_t>(((i % m) + m) % m);
  };
  const std::size_t i = p % nx, j = p / nx;
  return wrap(static_cast<std::ptrdiff_t>(i) + di, nx) + nx * wrap(static_cast<std::ptrdiff_t>(j) + dj, ny);
}

}  // namespace peristep::learning
