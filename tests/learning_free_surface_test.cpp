// The free-surface sums of 003:(30): a linear field with the model's traction-free lateral strain is an
// equilibrium of L_KN on a lattice with free top and bottom edges (003 Sec. 3.2: exact for linear
// fields), and it is not without those sums.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "learning/damaged_lps_operator.hpp"
#include "learning_support.hpp"

using namespace peristep::learning;
using namespace peristep::learning::testing;

TEST_CASE("the free-surface sums make a traction-free linear field an equilibrium at free edges", "[learning]") {
  const double h = 1.0, delta = 3.0, e11 = 0.01;
  const Truth t = syntheticTruth(delta);
  const CoarseGrid g{20, 20, 0.0, 0.0, h, h, false};
  DamagedLpsOperator op(g, makeLatticeStencil(h, h, delta), t.kernel, t.lambda, t.mu);
  const double e22 = -t.lambda / (t.lambda + 2 * t.mu) * e11;  // sigma22 = 0 (plane stress)
  std::vector<double> u(2 * g.size()), smax;
  for (std::size_t p = 0; p < g.size(); ++p) u[2 * p] = e11 * g.x(p), u[2 * p + 1] = e22 * g.y(p);
  op.updateMaxStretch(u, smax);
  // Largest |L_KN| at the points whose horizon stays off the left and right edges (sigma11 != 0 there),
  // against the size of one bond's share of the stress: (lambda + 2 mu) e11 / h.
  const auto largest = [&]() {
    const std::vector<double> L = op.apply(u, smax, 1e3);
    double m = 0;
    for (std::size_t p = 0; p < g.size(); ++p)
      if (g.x(p) >= delta && g.x(p) <= (g.nx - 1) * h - delta)
        m = std::max({m, std::abs(L[2 * p]), std::abs(L[2 * p + 1])});
    return m / ((t.lambda + 2 * t.mu) * e11 / h);
  };
  const double with = largest();
  op.setFreeSurfaceTerms(false);
  const double without = largest();
  INFO("largest relative force with the free-surface sums " << with << ", without " << without);
  CHECK(with < 1e-8);
  CHECK(without > 1e-2);
}
