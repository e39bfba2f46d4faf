#include "scenes/microstructure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/errors.hpp"

namespace peristep {

namespace {

// An ellipse with its axes' cosines and its bounding box half-widths.
struct PlacedEllipse {
  double cx, cy, c, s, wx, wy;
  const EllipseShape& e;
  PlacedEllipse(const Crystal& k, const EllipseShape& shape)
      : cx(k.cx), cy(k.cy), c(std::cos(k.angle)), s(std::sin(k.angle)), e(shape) {
    wx = std::hypot(e.semiMajor * c, e.semiMinor * s);
    wy = std::hypot(e.semiMajor * s, e.semiMinor * c);
  }
  // The x-interval of the ellipse on the line at height y (empty when a > b): u^2 + v^2 <= 1 is a
  // quadratic in x - cx.
  std::pair<double, double> chord(double y) const {
    const double dy = y - cy, a2 = e.semiMajor * e.semiMajor, b2 = e.semiMinor * e.semiMinor;
    const double A = c * c / a2 + s * s / b2, B = 2.0 * dy * c * s * (1.0 / a2 - 1.0 / b2);
    const double C = dy * dy * (s * s / a2 + c * c / b2) - 1.0, disc = B * B - 4.0 * A * C;
    if (disc < 0.0) return {1.0, 0.0};
    const double root = std::sqrt(disc);
    return {cx + (-B - root) / (2.0 * A), cx + (-B + root) / (2.0 * A)};
  }
  bool contains(double x, double y) const {
    const double dx = x - cx, dy = y - cy;
    const double u = (c * dx + s * dy) / e.semiMajor, v = (-s * dx + c * dy) / e.semiMinor;
    return u * u + v * v <= 1.0;
  }
};

// Index range [first, last] of cells (or grid lines) k with origin + k * step in [lo, hi], clipped to [0, n).
std::pair<std::int64_t, std::int64_t> indexRange(double lo, double hi, double origin, double step, std::size_t n) {
  const auto first = static_cast<std::int64_t>(std::ceil((lo - origin) / step));
  const auto last = static_cast<std::int64_t>(std::floor((hi - origin) / step));
  return {std::max<std::int64_t>(first, 0), std::min<std::int64_t>(last, static_cast<std::int64_t>(n) - 1)};
}

}  // namespace

std::vector<Crystal> placeCrystals(double Lx, double Ly, double f, std::uint64_t seed, EllipseShape e) {
  require(std::isfinite(f) && f >= 0.0 && f <= 1.0, "crystal volume fraction must lie in [0, 1]");
  require(Lx > 0.0 && Ly > 0.0, "the microstructure's domain must have a positive size");
  // Cell centres at x0 + (i + 1/2) * cell; the cell is adjusted so that whole cells tile the domain.
  const double target = e.semiMinor / kCoverRasterPerMinorAxis;
  const auto nx = static_cast<std::size_t>(std::max(1.0, std::round(Lx / target)));
  const auto ny = static_cast<std::size_t>(std::max(1.0, std::round(Ly / target)));
  const double cellX = Lx / static_cast<double>(nx), cellY = Ly / static_cast<double>(ny);
  const double x0 = -0.5 * Lx, y0 = -0.5 * Ly;
  std::vector<std::uint8_t> covered(nx * ny, 0);
  const double needed = f * static_cast<double>(nx * ny);
  std::size_t inside = 0;

  std::vector<Crystal> crystals;
  std::mt19937_64 rng(seed);
  const auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  while (static_cast<double>(inside) < needed) {
    Crystal k;
    k.cx = x0 + Lx * uniform();
    k.cy = y0 + Ly * uniform();
    k.angle = 2.0 * std::numbers::pi * uniform();
    crystals.push_back(k);
    // Scan the raster rows the crystal crosses, each over the x-interval the ellipse cuts out of it.
    const PlacedEllipse q(k, e);
    const auto [j0, j1] = indexRange(q.cy - q.wy, q.cy + q.wy, y0 + 0.5 * cellY, cellY, ny);
    for (std::int64_t j = j0; j <= j1; ++j) {
      const auto [xa, xb] = q.chord(y0 + (static_cast<double>(j) + 0.5) * cellY);
      const auto [i0, i1] = indexRange(xa, xb, x0 + 0.5 * cellX, cellX, nx);
      std::uint8_t* row = covered.data() + static_cast<std::size_t>(j) * nx;
      for (std::int64_t i = i0; i <= i1; ++i) {
        inside += row[i] ^ 1u;
        row[i] = 1;
      }
    }
  }
  return crystals;
}

std::vector<std::uint8_t> sampleCrystals(const PointCloud& c, std::span<const Crystal> crystals, EllipseShape e) {
  std::vector<std::uint8_t> R(c.size(), 0);
  // The cloud is a (possibly jittered) grid of gx x gy points from (x0, y0) in steps of h: each crystal
  // tests the grid points in its bounding box widened by one spacing for the jitter.
  const double Lx = static_cast<double>(c.nx - 1) * c.h, Ly = static_cast<double>(c.ny - 1) * c.h;
  const double layers = static_cast<double>(c.layers);
  const double x0 = -0.5 * Lx - layers * c.h, y0 = -0.5 * Ly - layers * c.h;
  const std::size_t gx = c.nx + 2 * c.layers, gy = c.ny + 2 * c.layers;
  for (const Crystal& k : crystals) {
    const PlacedEllipse q(k, e);
    const auto [j0, j1] = indexRange(q.cy - q.wy - c.h, q.cy + q.wy + c.h, y0, c.h, gy);
    const auto [i0, i1] = indexRange(q.cx - q.wx - c.h, q.cx + q.wx + c.h, x0, c.h, gx);
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i) {
        const auto p = static_cast<std::size_t>(j) * gx + static_cast<std::size_t>(i);
        if (!R[p] && q.contains(c.x[p], c.y[p])) R[p] = 1;
      }
  }
  return R;
}

std::vector<std::uint8_t> generateMicrostructure(const PointCloud& c, double f, std::uint64_t seed, EllipseShape e) {
  require(std::isfinite(f) && f >= 0.0 && f <= 1.0, "crystal volume fraction must lie in [0, 1]");
  if (f >= 1.0) return std::vector<std::uint8_t>(c.size(), 1);
  const double Lx = static_cast<double>(c.nx - 1) * c.h, Ly = static_cast<double>(c.ny - 1) * c.h;
  return sampleCrystals(c, placeCrystals(Lx, Ly, f, seed, e), e);
}

double crystalFraction(const PointCloud& c, const std::vector<std::uint8_t>& R) {
  std::size_t n = 0;
  for (std::size_t p : c.domain) n += R[p];
  return static_cast<double>(n) / static_cast<double>(c.domain.size());
}

}  // namespace peristep
