// Damage-criterion step of 003 (Algorithm 1 (v)) on a synthetic fracture run made by the same operator
// L_KN (003:(28)-(33)) with a known s0: the 1-D minimization must find it.
#include <catch2/catch.hpp>

#include <cmath>

#include "learning/critical_stretch_fit.hpp"
#include "learning/fracture_residual.hpp"
#include "learning_support.hpp"

using namespace peristep::learning;
using namespace peristep::learning::testing;

TEST_CASE("the critical stretch of a synthetic fracture run is recovered within 1%", "[learning]") {
  const double h = 1.0, delta = 3.0, s0 = 0.11, rho = 1.0, dt = 0.2, v0 = 0.15;
  const Truth t = syntheticTruth(delta);
  const LatticeStencil st = makeLatticeStencil(h, h, delta);
  FractureFrames run{CoarseGrid{24, 24, 0.0, 0.0, h, h, false}, dt, std::vector<double>(24 * 24, rho), {}, {}};
  const CoarseGrid& g = run.grid;
  // Three columns on each side (one horizon) move apart in x at +-v0 (1 - y/Ly): the lower edge opens first.
  const auto edge = [&](std::size_t p) { return p % g.nx < 3 || p % g.nx >= g.nx - 3; };
  const auto edgeU = [&](std::size_t p, double time) {
    return (p % g.nx < 3 ? -1.0 : 1.0) * v0 * (1.0 - g.y(p) / (g.ny * h)) * time;
  };
  const DamagedLpsOperator op(g, st, t.kernel, t.lambda, t.mu);
  std::vector<double> u(2 * g.size(), 0.0), prev = u, zero(2 * g.size(), 0.0), smax;
  run.u.push_back(u);
  run.b.push_back(zero);
  // Central differences 003:(20)-(21) with the bond states of the run so far: one frame per step.
  const int steps = 120;
  for (int n = 0; n < steps; ++n) {
    op.updateMaxStretch(u, smax);
    const std::vector<double> L = op.apply(u, smax, s0);
    std::vector<double> next(u.size());
    for (std::size_t p = 0; p < g.size(); ++p)
      for (int c = 0; c < 2; ++c) {
        const std::size_t i = 2 * p + static_cast<std::size_t>(c);
        next[i] = edge(p) ? (c == 0 ? edgeU(p, (n + 1) * dt) : 0.0) : 2 * u[i] - prev[i] - dt * dt * L[i] / rho;
      }
    prev = u;
    u = next;
    run.u.push_back(u);
    run.b.push_back(zero);
  }
  const FractureResidual res(run, op, 1, steps - 1, delta);
  double largest = 0;
  for (const double s : res.maxStretch(steps)) largest = std::max(largest, s);
  REQUIRE(largest > 2 * s0);  // bonds did break
  const CriticalStretchFit fit = fitCriticalStretch([&](double s) { return res.loss(s); }, 0.02, 0.3, 30);
  INFO("s0 found " << fit.s0 << " (true " << s0 << "), loss " << fit.loss << ", largest stretch " << largest);
  CHECK(std::abs(fit.s0 - s0) < 0.01 * s0);
  CHECK(fit.loss < 1e-12 * res.loss(0.3));
}
