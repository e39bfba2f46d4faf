#include "geometry/point_cloud.hpp"

#include <cmath>
#include <random>
#include <string>

#include "core/errors.hpp"
#include "core/number_text.hpp"

namespace peristep {

void validateHorizon(double deltaOverH) {
  require(std::isfinite(deltaOverH) && deltaOverH >= kMinDeltaOverH,
          "horizon smaller than the grid spacing: deltaOverH must be >= " + numberText(kMinDeltaOverH) + " (got " +
              numberText(deltaOverH) + ")");
  require(deltaOverH <= kMaxDeltaOverH,
          "deltaOverH must be <= " + numberText(kMaxDeltaOverH) + " (got " + numberText(deltaOverH) + ")");
}

void validate(const GridSpec& s) {
  require(s.nx >= kMinPointsPerSide && s.ny >= kMinPointsPerSide,
          "empty domain: nx and ny must both be at least " + std::to_string(kMinPointsPerSide) + " (got nx = " +
                                      std::to_string(s.nx) + ", ny = " + std::to_string(s.ny) + ")");
  require(std::isfinite(s.Lx) && std::isfinite(s.Ly) && s.Lx > 0 && s.Ly > 0,
          "empty domain: Lx and Ly must be positive and finite");
  const double hx = s.Lx / (static_cast<double>(s.nx) - 1), hy = s.Ly / (static_cast<double>(s.ny) - 1);
  require(std::abs(hx - hy) <= 1e-9 * hx, "grid spacing must be uniform: Lx/(nx-1) = " + std::to_string(hx) +
                                              " but Ly/(ny-1) = " + std::to_string(hy));
  validateHorizon(s.deltaOverH);
  require(std::isfinite(s.jitter) && s.jitter >= 0.0 && s.jitter < kMaxJitter,
          "jitter must lie in [0, " + numberText(kMaxJitter) + ") grid spacings (got " + numberText(s.jitter) + ")");
  const double points = static_cast<double>(s.nx) * static_cast<double>(s.ny);
  require(points < 2e8, "grid too large: nx*ny = " + std::to_string(points));
}

PointCloud makeRectangle(const GridSpec& spec) {
  validate(spec);
  PointCloud c;
  c.h = spec.h();
  c.delta = spec.delta();
  c.nx = spec.nx;
  c.ny = spec.ny;
  c.layers = spec.collar ? collarLayers(spec.deltaOverH) : 0;
  const std::size_t gx = c.nx + 2 * c.layers, gy = c.ny + 2 * c.layers;
  const std::size_t n = gx * gy;
  c.x.resize(n);
  c.y.resize(n);
  c.image.assign(n, -1);
  c.region.assign(n, Region::Dirichlet);
  c.domain.reserve(c.nx * c.ny);

  std::mt19937_64 rng(spec.seed);
  const auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };
  const double x0 = -0.5 * spec.Lx, y0 = -0.5 * spec.Ly;
  const auto L = static_cast<std::int64_t>(c.layers);
  for (std::size_t gj = 0; gj < gy; ++gj) {
    for (std::size_t gi = 0; gi < gx; ++gi) {
      const std::size_t p = gj * gx + gi;
      const auto ix = static_cast<std::int64_t>(gi) - L, iy = static_cast<std::int64_t>(gj) - L;
      c.x[p] = x0 + static_cast<double>(ix) * c.h;
      c.y[p] = y0 + static_cast<double>(iy) * c.h;
      if (spec.jitter > 0) {
        c.x[p] += spec.jitter * c.h * uniform();
        c.y[p] += spec.jitter * c.h * uniform();
      }
      if (ix >= 0 && iy >= 0 && ix < static_cast<std::int64_t>(c.nx) && iy < static_cast<std::int64_t>(c.ny)) {
        c.image[p] = iy * static_cast<std::int64_t>(c.nx) + ix;
        c.region[p] = Region::Domain;
        c.domain.push_back(p);
      }
    }
  }
  return c;
}

void PointCloud::freeSideEdges() {
  const std::size_t gx = nx + 2 * layers;
  for (std::size_t p = 0; p < size(); ++p) {
    const std::size_t gi = p % gx, gj = p / gx;
    const bool besideRows = gj >= layers && gj < layers + ny;
    const bool outsideColumns = gi < layers || gi >= layers + nx;
    if (besideRows && outsideColumns) region[p] = Region::Void;
  }
}

}  // namespace peristep
