// Prediction step of 003 (Sec. 5.2): a synthetic fracture run of the forward solver (003:(28)-(33) with
// central differences (20)-(21)) with a known kernel and s0, given to the prediction path as "frames",
// must come back, and its crack must grow from the slit.
#include <catch2/catch.hpp>

#include <cmath>

#include "learning/fracture_prediction.hpp"
#include "learning/prediction_window_loss.hpp"
#include "learning_support.hpp"

using namespace peristep::learning;
using namespace peristep::learning::testing;

namespace {

constexpr double kH = 1.0, kDelta = 3.0, kS0 = 0.11, kRho = 1.0, kInterval = 0.2, kV0 = 0.15;
const CoarseGrid kGrid{24, 24, 0.0, 0.0, kH, kH, false};

struct Synthetic {
  DamagedLpsOperator op;
  FractureDrive drive;
  FractureFrames frames;
};

// Three columns on each side (one horizon) move apart in x at +-v0 (1 - y/Ly), the lower edge opens
// first; a slit between columns 11 and 12 from the lower edge. `substeps` steps per frame interval.
Synthetic syntheticRun(std::size_t frames, std::size_t substeps) {
  const Truth t = syntheticTruth(kDelta);
  const CoarseGrid& g = kGrid;
  Synthetic s{DamagedLpsOperator(g, makeLatticeStencil(kH, kH, kDelta), t.kernel, t.lambda, t.mu), {}, {}};
  FractureDrive& d = s.drive;
  d.rho.assign(g.size(), kRho);
  for (std::size_t p = 0; p < g.size(); ++p) d.prescribed.push_back(p % g.nx < 3 || p % g.nx >= g.nx - 3);
  d.boundary = [g](double time, std::vector<double>& u) {
    for (std::size_t p = 0; p < g.size(); ++p)
      u[2 * p] = (p % g.nx < 12 ? -1.0 : 1.0) * kV0 * (1.0 - g.y(p) / (g.ny * kH)) * time, u[2 * p + 1] = 0.0;
  };
  const double dt = kInterval / static_cast<double>(substeps);
  d.u0.assign(2 * g.size(), 0.0);
  d.u1 = d.u0;
  std::vector<double> edge(2 * g.size());
  d.boundary(dt, edge);
  for (std::size_t p = 0; p < g.size(); ++p)
    if (d.prescribed[p]) d.u1[2 * p] = edge[2 * p];
  d.initialStretch = s.op.slit(11.5, -1.0, 11.5, 8.0);
  const FractureRun run = runFracture(s.op, d, kS0, dt, frames * substeps, substeps);
  REQUIRE(run.finite);
  REQUIRE(run.u.size() == frames + 1);
  s.frames = FractureFrames{g, kInterval, d.rho, run.u, std::vector<std::vector<double>>(frames + 1, d.u0)};
  return s;
}

PredictionSetup setupFor(const Synthetic& s, std::size_t substeps) {
  PredictionSetup setup;
  setup.prescribed = s.drive.prescribed;
  setup.initialStretch = s.drive.initialStretch;
  setup.s0 = kS0;
  setup.substeps = substeps;
  setup.lastFrame = s.frames.u.size() - 1;
  return setup;
}

}  // namespace

TEST_CASE("a synthetic fracture run is reproduced by the prediction path and cracks from the slit", "[learning]") {
  const Synthetic s = syntheticRun(120, 1);
  const PredictionSetup setup = setupFor(s, 1);
  const FractureRun run = predictFracture(s.op, s.frames, setup);
  const PredictionError err = predictionError(s.op, s.frames, run, setup);
  INFO("displacement error " << err.displacement << ", damage error " << err.damage);
  CHECK(err.displacement < 1e-12);
  CHECK(err.damage < 1e-12);

  // The crack: damage 003:(46) above the slit tip (x = 11.5, y = 8) grows, more than beside it.
  const std::vector<double> first = s.op.damage(run.maxStretch.front(), kS0);
  const std::vector<double> last = s.op.damage(run.maxStretch.back(), kS0);
  const std::size_t aboveTip = 11 + kGrid.nx * 12, beside = 6 + kGrid.nx * 12;
  INFO("damage above the tip: " << first[aboveTip] << " -> " << last[aboveTip] << "; beside it " << last[beside]);
  CHECK(last[aboveTip] > first[aboveTip] + 0.2);
  CHECK(last[aboveTip] > 2 * last[beside]);
}

TEST_CASE("with sub-steps the prediction of a synthetic run differs only by its estimated start", "[learning]") {
  // Data made with 4 steps per frame from rest; the prediction starts from the frame velocity
  // (u_1 - u_0) / interval instead, so the free points' first sub-step differs by O(interval^2).
  const Synthetic s = syntheticRun(30, 4);
  const PredictionSetup setup = setupFor(s, 4);
  const PredictionError err = predictionError(s.op, s.frames, predictFracture(s.op, s.frames, setup), setup);
  INFO("displacement error " << err.displacement << ", damage error " << err.damage);
  CHECK(err.displacement < 1e-2);
  CHECK(err.damage < 1e-2);
}

TEST_CASE("the critical stretch of a synthetic run is recovered from the error of a restarted prediction", "[learning]") {
  // The project's s0 step (learning/prediction_window_loss.hpp) on a run whose crack grows inside the window.
  const Synthetic s = syntheticRun(120, 1);
  const std::size_t first = 10, last = 100;
  std::vector<double> smax = s.drive.initialStretch;
  for (std::size_t f = 0; f <= first; ++f) s.op.updateMaxStretch(s.frames.u[f], smax);
  const std::vector<double> atFirst = s.op.damage(smax, kS0);
  for (std::size_t f = first; f <= last; ++f) s.op.updateMaxStretch(s.frames.u[f], smax);
  const std::vector<double> atLast = s.op.damage(smax, kS0);
  double grown = 0;
  for (std::size_t p = 0; p < atLast.size(); ++p) grown += atLast[p] - atFirst[p];
  INFO("damage summed over the points: " << grown << " added in the window");
  REQUIRE(grown > 1.0);

  const PredictionWindowLoss window(s.op, s.frames, setupFor(s, 1), first, last);
  CHECK(window.frames() == last - first);
  const auto loss = [&](double s0) { return window(s0); };
  CriticalStretchFit fit = fitCriticalStretch(loss, 0.02, 0.3, 30);
  criticalStretchInterval(loss, static_cast<double>(window.frames()), fit);
  INFO("s0 found " << fit.s0 << " in [" << fit.lower << ", " << fit.upper << "], loss " << fit.loss << " against "
                   << window(0.3) << " at 0.3");
  CHECK(std::abs(fit.s0 - kS0) < 0.01 * kS0);
  CHECK(fit.loss < 1e-12 * window(0.3));
  // Without noise the interval shrinks to the minimum (to the bisection's tolerance).
  CHECK(fit.lower <= fit.s0);
  CHECK(fit.upper >= fit.s0);
  CHECK(std::abs(fit.lower - kS0) < 1e-3 * kS0);
  CHECK(std::abs(fit.upper - kS0) < 1e-3 * kS0);
}
