// Prediction step of 003 (Sec. 5.2): a synthetic fracture run of the forward solver (003:(28)-(33) with
// central differences (20)-(21)) with a known kernel and s0, given to the prediction path as "frames",
// must come back unchanged, and its crack must grow from the slit.
#include <catch2/catch.hpp>

#include <cmath>

#include "learning/fracture_prediction.hpp"
#include "learning_support.hpp"

using namespace peristep::learning;
using namespace peristep::learning::testing;

TEST_CASE("a synthetic fracture run is reproduced by the prediction path and cracks from the slit", "[learning]") {
  const double h = 1.0, delta = 3.0, s0 = 0.11, rho = 1.0, dt = 0.2, v0 = 0.15;
  const std::size_t steps = 120;
  const Truth t = syntheticTruth(delta);
  const CoarseGrid g{24, 24, 0.0, 0.0, h, h, false};
  const DamagedLpsOperator op(g, makeLatticeStencil(h, h, delta), t.kernel, t.lambda, t.mu);
  // Three columns on each side (one horizon) move apart in x at +-v0 (1 - y/Ly): the lower edge opens first.
  FractureDrive drive;
  drive.rho.assign(g.size(), rho);
  for (std::size_t p = 0; p < g.size(); ++p) drive.prescribed.push_back(p % g.nx < 3 || p % g.nx >= g.nx - 3);
  drive.boundary = [&](double time, std::vector<double>& u) {
    for (std::size_t p = 0; p < g.size(); ++p)
      u[2 * p] = (p % g.nx < 12 ? -1.0 : 1.0) * v0 * (1.0 - g.y(p) / (g.ny * h)) * time, u[2 * p + 1] = 0.0;
  };
  drive.u0.assign(2 * g.size(), 0.0);
  drive.u1 = drive.u0;
  std::vector<double> edge(2 * g.size());
  drive.boundary(dt, edge);
  for (std::size_t p = 0; p < g.size(); ++p)
    if (drive.prescribed[p]) drive.u1[2 * p] = edge[2 * p];
  drive.initialStretch = op.slit(11.5, -1.0, 11.5, 8.0);  // between columns 11 and 12, from the lower edge
  const FractureRun truth = runFracture(op, drive, s0, dt, steps, 1);
  REQUIRE(truth.finite);
  REQUIRE(truth.u.size() == steps + 1);

  FractureFrames frames{g, dt, drive.rho, truth.u, std::vector<std::vector<double>>(steps + 1, drive.u0)};
  PredictionSetup setup;
  setup.prescribed = drive.prescribed;
  setup.initialStretch = drive.initialStretch;
  setup.s0 = s0;
  setup.substeps = 1;
  setup.lastFrame = steps;
  const FractureRun run = predictFracture(op, frames, setup);
  const PredictionError err = predictionError(op, frames, run, setup);
  INFO("displacement error " << err.displacement << ", damage error " << err.damage);
  CHECK(err.displacement < 1e-12);
  CHECK(err.damage < 1e-12);

  // The crack: damage 003:(46) above the slit tip (x = 11.5, y = 8) grows, more than beside it.
  const std::vector<double> first = op.damage(run.maxStretch.front(), s0), last = op.damage(run.maxStretch.back(), s0);
  const std::size_t aboveTip = 11 + g.nx * 12, beside = 6 + g.nx * 12;
  INFO("damage above the tip: " << first[aboveTip] << " -> " << last[aboveTip] << "; beside it " << last[beside]);
  CHECK(last[aboveTip] > first[aboveTip] + 0.2);
  CHECK(last[aboveTip] > 2 * last[beside]);
}
