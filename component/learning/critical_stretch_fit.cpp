#include "learning/critical_stretch_fit.hpp"

#include <algorithm>
#include <cmath>

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
  // Golden sections on the bracket around the best scan point.
  double a = fit.scanS0[best > 0 ? best - 1 : 0], b = fit.scanS0[std::min<std::size_t>(best + 1, points - 1)];
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a), fc = loss(c), fd = loss(d);
  fit.evaluations += 2;
  while (b - a > 1e-7 * (std::abs(a) + std::abs(b))) {
    if (fc < fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = loss(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = loss(d);
    }
    ++fit.evaluations;
  }
  fit.s0 = 0.5 * (a + b);
  fit.loss = loss(fit.s0);
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
