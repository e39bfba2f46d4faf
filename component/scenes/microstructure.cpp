#include "scenes/microstructure.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "core/errors.hpp"

namespace peristep {

std::vector<std::uint8_t> generateMicrostructure(const PointCloud& c, double f, std::uint64_t seed,
                                                 EllipseShape e) {
  require(std::isfinite(f) && f >= 0.0 && f <= 1.0, "crystal volume fraction must lie in [0, 1]");
  std::vector<std::uint8_t> R(c.size(), 0);
  if (f >= 1.0) {
    R.assign(c.size(), 1);
    return R;
  }
  const double Lx = static_cast<double>(c.nx - 1) * c.h, Ly = static_cast<double>(c.ny - 1) * c.h;
  const double x0 = -0.5 * Lx, y0 = -0.5 * Ly;
  const std::size_t gx = c.nx + 2 * c.layers, gy = c.ny + 2 * c.layers;
  const double target = f * static_cast<double>(c.domain.size());
  std::size_t inside = 0;
  std::mt19937_64 rng(seed);
  const auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const auto reach = static_cast<std::int64_t>(std::ceil(e.semiMajor / c.h)) + 1;
  while (static_cast<double>(inside) < target) {
    const double cx = x0 + Lx * uniform(), cy = y0 + Ly * uniform(), angle = 2.0 * std::numbers::pi * uniform();
    const double ca = std::cos(angle), sa = std::sin(angle);
    // Grid indices around the centre: only points within the semi-major axis can be inside.
    const auto gi0 = static_cast<std::int64_t>(std::floor((cx - x0) / c.h)) + static_cast<std::int64_t>(c.layers);
    const auto gj0 = static_cast<std::int64_t>(std::floor((cy - y0) / c.h)) + static_cast<std::int64_t>(c.layers);
    for (std::int64_t gj = std::max<std::int64_t>(0, gj0 - reach); gj <= std::min<std::int64_t>(gy - 1, gj0 + reach); ++gj)
      for (std::int64_t gi = std::max<std::int64_t>(0, gi0 - reach); gi <= std::min<std::int64_t>(gx - 1, gi0 + reach); ++gi) {
        const auto p = static_cast<std::size_t>(gj) * gx + static_cast<std::size_t>(gi);
        if (R[p]) continue;
        const double dx = c.x[p] - cx, dy = c.y[p] - cy;
        const double u = (ca * dx + sa * dy) / e.semiMajor, v = (-sa * dx + ca * dy) / e.semiMinor;
        if (u * u + v * v <= 1.0) {
          R[p] = 1;
          if (c.inDomain(p)) ++inside;
        }
      }
  }
  return R;
}

double crystalFraction(const PointCloud& c, const std::vector<std::uint8_t>& R) {
  std::size_t n = 0;
  for (std::size_t p : c.domain) n += R[p];
  return static_cast<double>(n) / static_cast<double>(c.domain.size());
}

}  // namespace peristep
