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
  // Scan points on each side of s0 up to the first one outside; bisection between it and the last inside.
  const auto end = [&](int direction) {
    const auto n = static_cast<std::ptrdiff_t>(fit.scanS0.size());
    auto i = std::lower_bound(fit.scanS0.begin(), fit.scanS0.end(), fit.s0) - fit.scanS0.begin();
    if (direction < 0) --i;
    double in = fit.s0;
    for (; i >= 0 && i < n; i += direction) {
      if (!inside(fit.scanLoss[i])) break;
      in = fit.scanS0[i];
    }
    if (i < 0 || i >= n) return in;
    double out = fit.scanS0[i];
    while (std::abs(out - in) > 1e-6 * std::abs(fit.s0)) {
      const double mid = 0.5 * (in + out);
      (inside(loss(mid)) ? in : out) = mid;
      ++fit.evaluations;
    }
    return in;
  };
  fit.lower = end(-1), fit.upper = end(+1);
}

}  // namespace peristep::learning
