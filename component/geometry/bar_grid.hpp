#pragma once
// Points of the 1D bar of 002 Sec. 4.3: a uniform grid, or the stochastic grid of 002:(36),
//   spacing = h + jitter sign(randn()) rand() h      (jitter = 0.65 in 002),
// rescaled so that the bar keeps its length L ((36) alone does not). Points cannot overlap: every
// spacing is at least (1 - jitter) h before the rescaling, so the rejection of 002 Sec. 4.3 never acts.
#include <vector>

#include "random/weibull_scatter.hpp"

namespace peristep {

// The jitter of 002's stochastic grid.
inline constexpr double kStochasticGridJitter = 0.65;

// bonds + 1 increasing positions from 0 to length; jitter = 0 gives the uniform grid (stream unused).
std::vector<double> barGrid(double length, int bonds, double jitter, ScatterStream& stream);

}  // namespace peristep
