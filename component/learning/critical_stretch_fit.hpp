#pragma once
// The 1-D minimization of the damage-criterion step (003 Algorithm 1 (v); 003 uses bisection): a uniform scan,
// then Brent's method around the best scan point, for any loss of s0 alone (the equation residual 003:(42),
// learning/fracture_residual.hpp, or the prediction error of learning/prediction_window_loss.hpp).
#include <functional>
#include <limits>
#include <vector>

namespace peristep::learning {

struct CriticalStretchFit {
  double s0 = 0, loss = 0;
  std::vector<double> scanS0, scanLoss;
  int evaluations = 0;
  // 95% profile interval (criticalStretchInterval); NaN until computed.
  double lower = std::numeric_limits<double>::quiet_NaN(), upper = lower;
};

// Minimum of loss(s0) on [lo, hi]: a uniform scan of `points`, then Brent's method (Boost.Math) between the
// best point's neighbours. `evaluations` counts every call of the loss.
CriticalStretchFit fitCriticalStretch(const std::function<double(double)>& loss, double lo, double hi,
                                      int points = 60);

// The smallest range of s0 that holds every s0 with loss <= fit.loss exp(3.84 / n): the likelihood-ratio 95%
// region of a least-squares loss made of n independent Gaussian observations with unknown variance (chi^2_1
// quantile 3.84), closed over its gaps (a rough loss can dip below the bound away from its minimum). The ends
// are the outermost scan points inside, refined by bisection towards their outer neighbours; an end at the
// scan's bound is that bound.
void criticalStretchInterval(const std::function<double(double)>& loss, double observations, CriticalStretchFit& fit);

}  // namespace peristep::learning
