#include "learning/coarse_graining.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/errors.hpp"

namespace peristep::learning {

double smoothnessIndicator(std::span<const double> d, std::span<const double> U, double from, double to) {
  const std::size_t n = d.size();
  if (n < 2 * kMinPart) return 1.0;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d[a] < d[b]; });
  // Prefix sums of 1, d, d^2, U, d U, U^2 give the least-squares line error of any contiguous part, (6)-(8);
  // of centred data, so that a constant U gives exactly 0 and not round-off.
  double dm = 0, Um = 0;
  for (std::size_t i = 0; i < n; ++i) dm += d[i] / static_cast<double>(n), Um += U[i] / static_cast<double>(n);
  std::vector<double> s[6];
  for (auto& v : s) v.assign(n + 1, 0.0);
  double scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = d[order[i]] - dm, y = U[order[i]] - Um;
    scale = std::max(scale, std::abs(y));
    const double terms[6] = {1.0, x, x * x, y, x * y, y * y};
    for (int k = 0; k < 6; ++k) s[k][i + 1] = s[k][i] + terms[k];
  }
  const auto lineError = [&](std::size_t a, std::size_t b) {  // points [a, b)
    const double N = s[0][b] - s[0][a], Sx = s[1][b] - s[1][a], Sxx = s[2][b] - s[2][a];
    const double Sy = s[3][b] - s[3][a], Sxy = s[4][b] - s[4][a], Syy = s[5][b] - s[5][a];
    const double vx = Sxx - Sx * Sx / N, vxy = Sxy - Sx * Sy / N, vy = Syy - Sy * Sy / N;
    const double e = vx > 1e-12 * (Sxx + 1e-300) ? vy - vxy * vxy / vx : vy;  // coincident d: a constant fit
    return std::max(e, 0.0);
  };
  const double e0 = lineError(0, n);
  if (!(e0 > 1e-24 * scale * scale * static_cast<double>(n))) return 1.0;
  double best = e0;
  for (std::size_t k = kMinPart; k + kMinPart <= n; ++k) {
    const double at = 0.5 * (d[order[k - 1]] + d[order[k]]);  // where this split puts the jump
    if (at > from && at < to) best = std::min(best, lineError(0, k) + lineError(k, n));
  }
  return best / e0;
}

CoarseGraining::CoarseGraining(CoarseGrid grid, std::vector<double> X, std::vector<double> Y, std::vector<double> mass,
                               double radius, double thickness, double band)
    : grid_(grid), X_(std::move(X)), Y_(std::move(Y)), mass_(std::move(mass)), radius_(radius), thickness_(thickness),
      band_(band) {
  require(X_.size() == Y_.size() && X_.size() == mass_.size(), "coarse-graining: X, Y and mass differ in size");
  require(radius > 0 && grid.hx > 0 && grid.hy > 0 && grid.size() > 0, "coarse-graining: empty grid or radius");
  const double Lx = static_cast<double>(grid.nx) * grid.hx, Ly = static_cast<double>(grid.ny) * grid.hy;
  links_.resize(grid.size());
  // Bin particles into cells of side >= R so each grid point looks at 3 x 3 cells (periodic: wrapped).
  const double xmin = *std::min_element(X_.begin(), X_.end()), ymin = *std::min_element(Y_.begin(), Y_.end());
  const double xmax = *std::max_element(X_.begin(), X_.end()), ymax = *std::max_element(Y_.begin(), Y_.end());
  const auto cx = static_cast<std::ptrdiff_t>(std::max(1.0, std::floor((xmax - xmin) / radius)));
  const auto cy = static_cast<std::ptrdiff_t>(std::max(1.0, std::floor((ymax - ymin) / radius)));
  const double wx = (xmax - xmin) / static_cast<double>(cx) * (1 + 1e-12) + 1e-300;
  const double wy = (ymax - ymin) / static_cast<double>(cy) * (1 + 1e-12) + 1e-300;
  require(!grid.periodic || (cx >= 3 && cy >= 3), "coarse-graining: a periodic box must span 3 radii");
  std::vector<std::vector<std::size_t>> cells(static_cast<std::size_t>(cx * cy));
  for (std::size_t e = 0; e < X_.size(); ++e) {
    const auto i = std::min(cx - 1, static_cast<std::ptrdiff_t>((X_[e] - xmin) / wx));
    const auto j = std::min(cy - 1, static_cast<std::ptrdiff_t>((Y_[e] - ymin) / wy));
    cells[static_cast<std::size_t>(i + cx * j)].push_back(e);
  }
  for (std::size_t p = 0; p < grid.size(); ++p) {
    const double x = grid.x(p), y = grid.y(p);
    const auto ci = static_cast<std::ptrdiff_t>(std::floor((x - xmin) / wx));
    const auto cj = static_cast<std::ptrdiff_t>(std::floor((y - ymin) / wy));
    for (std::ptrdiff_t j = cj - 1; j <= cj + 1; ++j)
      for (std::ptrdiff_t i = ci - 1; i <= ci + 1; ++i) {
        std::ptrdiff_t ii = i, jj = j;
        if (grid.periodic) {
          ii = ((i % cx) + cx) % cx;
          jj = ((j % cy) + cy) % cy;
        } else if (i < 0 || j < 0 || i >= cx || j >= cy) {
          continue;
        }
        for (const std::size_t e : cells[static_cast<std::size_t>(ii + cx * jj)]) {
          double dx = X_[e] - x, dy = Y_[e] - y;
          if (grid.periodic) {
            dx -= Lx * std::round(dx / Lx);
            dy -= Ly * std::round(dy / Ly);
          }
          const double r = std::hypot(dx, dy);
          if (r < radius) links_[p].push_back({e, dx, dy, radius - r});
        }
      }
  }
}

CoarseFields CoarseGraining::average(std::span<const double> U, std::span<const double> B, bool adaptive) const {
  const std::size_t np = X_.size();
  require(U.size() == 2 * np && B.size() == 2 * np, "coarse-graining: U or B does not match the particles");
  // tau * alpha per link, and its sum over grid points per particle (the denominator of 003:(4)/(5)).
  std::vector<std::vector<double>> weight(grid_.size());
  std::vector<double> total(np, 0.0);
  std::vector<double> d, Up;
  for (std::size_t p = 0; p < grid_.size(); ++p) {
    const auto& links = links_[p];
    weight[p].resize(links.size());
    for (std::size_t l = 0; l < links.size(); ++l) {
      double alpha = 1.0;
      if (adaptive) {
        // 003 Sec. 2: particles near x projected on the segment x -> X_e, displacement along it.
        const double L = std::hypot(links[l].dx, links[l].dy);
        if (L > 0) {
          const double ex = links[l].dx / L, ey = links[l].dy / L;
          d.clear(), Up.clear();
          for (const Link& o : links) {
            const double s = o.dx * ex + o.dy * ey;
            if (std::abs(o.dx * ey - o.dy * ex) > band_) continue;
            d.push_back(s);
            Up.push_back(U[2 * o.particle] * ex + U[2 * o.particle + 1] * ey);
          }
          alpha = smoothnessIndicator(d, Up, 0.0, L);
        }
      }
      weight[p][l] = links[l].tau * alpha;
      total[links[l].particle] += weight[p][l];
    }
  }
  CoarseFields f;
  f.rho.assign(grid_.size(), 0.0);
  f.u.assign(2 * grid_.size(), 0.0);
  f.b.assign(2 * grid_.size(), 0.0);
  const double volume = grid_.hx * grid_.hy * thickness_;  // discrete weights sum to 1: per-volume fields
  for (std::size_t p = 0; p < grid_.size(); ++p) {
    double mass = 0.0;
    for (std::size_t l = 0; l < links_[p].size(); ++l) {
      const std::size_t e = links_[p][l].particle;
      if (!(total[e] > 0)) continue;
      const double w = weight[p][l] / total[e];  // 003:(5)
      mass += w * mass_[e];
      for (int c = 0; c < 2; ++c) {
        f.u[2 * p + c] += w * mass_[e] * U[2 * e + c];
        f.b[2 * p + c] += w * B[2 * e + c];
      }
    }
    f.rho[p] = mass / volume;  // 003:(10)
    for (int c = 0; c < 2; ++c) {
      f.u[2 * p + c] = mass > 0 ? f.u[2 * p + c] / mass : 0.0;  // 003:(12)
      f.b[2 * p + c] /= volume;                                  // 003:(11)
    }
  }
  return f;
}

}  // namespace peristep::learning
