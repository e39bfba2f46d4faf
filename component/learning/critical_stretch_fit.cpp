#include "learning/critical_stretch_fit.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/errors.hpp"

namespace peristep::learning {

CriticalStretchFit fitCriticalStretch(const std::function<double(double)>& loss, double lo, double hi, int points) {
  require(hi > lo && points >= 3, "critical stretch fit: need lo < hi and >= 3 scan points");
  CriticalStretchFit fit;
  std::size_t best = 0;
  for (int i = 0; i < points; ++i) {
    const double s = lo + (hi - lo) * i / (points - 1);
    fit.scanS0.push_back(s);
    fit.scanLoss.push_back(loss(s));
    if (fit.scanLoss.back() < fit.scanLoss[best]) best = static_cast<std::size_t>(i);
  }
  fit.evaluations = points;
  // Brent's method (Boost.Math) on the bracket around the best scan point: parabolic steps where the loss is
  // smooth, golden sections where it is not (docs/decisions/0024-brent-for-the-critical-stretch.md). Half
  // the digits of a double: the most the method's tolerance may ask of a minimum.
  const double a = fit.scanS0[best > 0 ? best - 1 : 0], b = fit.scanS0[std::min<std::size_t>(best + 1, points - 1)];
  std::uintmax_t iterations = 200;
  const auto [s0, value] = boost::math::tools::brent_find_minima(
      [&](double s) {
        ++fit.evaluations;
        return loss(s);
      },
      a, b, std::numeric_limits<double>::digits / 2, iterations);
  fit.s0 = s0, fit.loss = value;
  if (fit.scanLoss[best] < fit.loss) fit.s0 = fit.scanS0[best], fit.loss = fit.scanLoss[best];
  return fit;
}

void criticalStretchInterval(const std::function<double(double)>& loss, double observations, CriticalStretchFit& fit) {
  require(observations > 0 && !fit.scanS0.empty(), "critical stretch interval: needs a fit and observations > 0");
  const double bound = fit.loss * std::exp(3.84 / observations);
  const auto inside = [&](double v) { return v <= bound; };
  // The outermost scan points inside (or s0), then bisection towards their outer neighbours.
  const auto n = static_cast<std::ptrdiff_t>(fit.scanS0.size());
  std::ptrdiff_t first = n, last = -1;
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (inside(fit.scanLoss[static_cast<std::size_t>(i)])) first = std::min(first, i), last = i;
  const auto refine = [&](double in, std::ptrdiff_t outIndex) {
    if (outIndex < 0 || outIndex >= n) return in;
    double out = fit.scanS0[static_cast<std::size_t>(outIndex)];
    while (std::abs(out - in) > 1e-6 * std::abs(fit.s0)) {
      const double mid = 0.5 * (in + out);
      (inside(loss(mid)) ? in : out) = mid;
      ++fit.evaluations;
    }
    return in;
  };
  const double lowest = first < n ? std::min(fit.s0, fit.scanS0[static_cast<std::size_t>(first)]) : fit.s0;
  const double highest = last >= 0 ? std::max(fit.s0, fit.scanS0[static_cast<std::size_t>(last)]) : fit.s0;
  const auto below = std::lower_bound(fit.scanS0.begin(), fit.scanS0.end(), lowest) - fit.scanS0.begin() - 1;
  const auto above = std::upper_bound(fit.scanS0.begin(), fit.scanS0.end(), highest) - fit.scanS0.begin();
  fit.lower = refine(lowest, below), fit.upper = refine(highest, above);
}

}  // namespace peristep::learning
