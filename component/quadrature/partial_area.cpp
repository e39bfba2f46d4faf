#include "quadrature/partial_area.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace peristep {
namespace {

// Antiderivative of s(x) = sqrt(R^2 - x^2) on [-R, R].
double circleArea(double x, double R) {
  const double s = std::sqrt(std::max(0.0, R * R - x * x));
  return 0.5 * (x * s + R * R * std::asin(std::clamp(x / R, -1.0, 1.0)));
}

}  // namespace

double rectangleDiskOverlap(double x0, double x1, double y0, double y1, double R) {
  const double a = std::max(x0, -R), b = std::min(x1, R);
  if (!(b > a) || !(y1 > y0) || !(R > 0)) return 0.0;
  // The chord length inside the rectangle, min(y1, s) - max(y0, -s) with s = sqrt(R^2 - x^2), keeps
  // one closed form between the abscissae where s crosses |y0| or |y1|: split the interval there.
  std::array<double, 6> cuts{a, b, b, b, b, b};  // unused slots repeat b: empty subintervals
  std::size_t n = 2;
  for (const double y : {y0, y1})
    if (std::abs(y) < R) {
      const double xc = std::sqrt(R * R - y * y);
      for (const double c : {-xc, xc})
        if (c > a && c < b) cuts[n++] = c;
    }
  std::sort(cuts.begin(), cuts.end());
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double l = cuts[k], r = cuts[k + 1];
    if (!(r > l)) continue;
    const double m = 0.5 * (l + r), s = std::sqrt(std::max(0.0, R * R - m * m));
    const bool topIsCircle = s < y1, bottomIsCircle = -s > y0;
    if ((topIsCircle ? s : y1) - (bottomIsCircle ? -s : y0) <= 0) continue;  // chord misses the rectangle
    const double arc = circleArea(r, R) - circleArea(l, R);
    area += (topIsCircle ? arc : y1 * (r - l)) - (bottomIsCircle ? -arc : y0 * (r - l));
  }
  return area;
}

double partialAreaFraction(double dx, double dy, double h, double eps) {
  const double half = 0.5 * h;
  return rectangleDiskOverlap(dx - half, dx + half, dy - half, dy + half, eps) / (h * h);
}

}  // namespace peristep
