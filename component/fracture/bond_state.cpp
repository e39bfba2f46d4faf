#include "fracture/bond_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <omp.h>

#include "core/parallel_errors.hpp"
#include "models/lps_material.hpp"

namespace peristep {

BondState makeBondState(const PointCloud& c, const Neighbours& nb, const std::vector<double>& lambda,
                        const std::vector<double>& mu, const std::vector<double>& G) {
  BondState s;
  s.intact.assign(nb.bonds(), 1);
  s.reverse.resize(nb.bonds());
  s.criticalStretch.assign(nb.bonds(), std::numeric_limits<double>::infinity());
  const double beta = 3.0 * c.delta / (4.0 * std::numbers::pi);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ps = 0; ps < static_cast<std::ptrdiff_t>(c.size()); ++ps) {
    const auto p = static_cast<std::size_t>(ps);
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      const std::uint32_t q = nb.index[k];
      const auto first = nb.index.begin() + static_cast<std::ptrdiff_t>(nb.begin(q));
      const auto last = nb.index.begin() + static_cast<std::ptrdiff_t>(nb.end(q));
      s.reverse[k] = static_cast<std::size_t>(std::lower_bound(first, last, static_cast<std::uint32_t>(p)) -
                                              nb.index.begin());
      if (c.isVoid(p) || c.isVoid(q)) {
        s.intact[k] = 0;
      } else if (c.inDomain(p) && c.inDomain(q)) {
        const double lam = harmonicMean(lambda[p], lambda[q]), m = harmonicMean(mu[p], mu[q]);
        const double g = 0.5 * (G[p] + G[q]);
        s.criticalStretch[k] = std::sqrt(g / (4.0 * (lam - m) * beta + 8.0 * m * beta));
      }
    }
  }
  return s;
}

namespace {

// Orientation of point (x, y) against the directed line a -> b: +1 left or on it, -1 right.
int side(const Segment& l, double x, double y) {
  const double cross = (l.x1 - l.x0) * (y - l.y0) - (l.y1 - l.y0) * (x - l.x0);
  return cross >= 0 ? 1 : -1;
}

bool crosses(const Segment& crack, double ax, double ay, double bx, double by) {
  const Segment bond{ax, ay, bx, by};
  return side(crack, ax, ay) != side(crack, bx, by) && side(bond, crack.x0, crack.y0) != side(bond, crack.x1, crack.y1);
}

}  // namespace

std::size_t breakCrossing(BondState& s, const PointCloud& c, const Neighbours& nb, const Segment& crack) {
  std::size_t broken = 0;
  for (std::size_t p = 0; p < c.size(); ++p)
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      const std::uint32_t q = nb.index[k];
      if (q < p || !s.intact[k]) continue;
      if (crosses(crack, c.x[p], c.y[p], c.x[q], c.y[q])) {
        s.intact[k] = s.intact[s.reverse[k]] = 0;
        ++broken;
      }
    }
  return broken;
}

namespace {
// The stretch of bond p -> nb.index[k] under the displacement u (000:(2.25)'s s, geometrically exact).
double bondStretch(const PointCloud& c, const Neighbours& nb, const std::vector<double>& u, std::size_t p,
                   std::size_t k) {
  const std::uint32_t q = nb.index[k];
  const double zx = c.x[q] - c.x[p], zy = c.y[q] - c.y[p];
  const double r = std::hypot(zx, zy);
  return (std::hypot(zx + u[2 * q] - u[2 * p], zy + u[2 * q + 1] - u[2 * p + 1]) - r) / r;
}
}  // namespace

std::vector<double> stretchRatios(const BondState& s, const PointCloud& c, const Neighbours& nb,
                                  const std::vector<double>& u) {
  std::vector<double> ratio(c.size(), 0.0);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ps = 0; ps < static_cast<std::ptrdiff_t>(c.size()); ++ps) {
    const auto p = static_cast<std::size_t>(ps);
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k)
      if (s.intact[k] && std::isfinite(s.criticalStretch[k]))
        ratio[p] = std::max(ratio[p], bondStretch(c, nb, u, p, k) / s.criticalStretch[k]);
  }
  return ratio;
}

OverstretchVerdict findOverstretched(const BondState& s, const PointCloud& c, const Neighbours& nb,
                                     const std::vector<double>& u, double uError) {
  // Threads check contiguous point ranges and the lists are joined in thread order: the result (and the
  // breaking order recorded from it) is the same for any number of threads.
  std::vector<std::vector<std::size_t>> found(static_cast<std::size_t>(omp_get_max_threads()));
  ParallelErrors errors;  // push_back allocates
  bool certain = true;
#pragma omp parallel num_threads(static_cast<int>(found.size())) reduction(&& : certain)
  {
    std::vector<std::size_t>& mine = found[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (std::ptrdiff_t ps = 0; ps < static_cast<std::ptrdiff_t>(c.size()); ++ps) errors.capture([&] {
      const auto p = static_cast<std::size_t>(ps);
      for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
        if (nb.index[k] < p || !s.intact[k] || !std::isfinite(s.criticalStretch[k])) continue;
        const double stretch = bondStretch(c, nb, u, p, k);
        if (stretch > s.criticalStretch[k]) mine.push_back(k);
        if (uError > 0) {  // |u_q - u_p| changes by at most 2 sqrt(2) uError, the stretch by that over |xi|
          const std::uint32_t q = nb.index[k];
          const double length = std::hypot(c.x[q] - c.x[p], c.y[q] - c.y[p]);
          if (std::abs(stretch - s.criticalStretch[k]) <= 2.0 * std::numbers::sqrt2 * uError / length) certain = false;
        }
      }
    });
  }
  errors.rethrow();
  OverstretchVerdict v;
  v.certain = certain;
  for (const auto& f : found) v.bonds.insert(v.bonds.end(), f.begin(), f.end());
  return v;
}

void breakBonds(BondState& s, std::span<const std::size_t> bonds) {
  for (std::size_t k : bonds) s.intact[k] = s.intact[s.reverse[k]] = 0;  // 000:(2.24): never heal
}

std::vector<std::size_t> breakOverstretched(BondState& s, const PointCloud& c, const Neighbours& nb,
                                            const std::vector<double>& u) {
  std::vector<std::size_t> fresh = findOverstretched(s, c, nb, u, 0.0).bonds;
  breakBonds(s, fresh);
  return fresh;
}

std::vector<std::uint8_t> intactBonds(const PointCloud& c, const Neighbours& nb, const std::vector<Segment>& cracks) {
  // The geometry of a bond state alone: its critical stretches are not read.
  const std::vector<double> unit(c.size(), 1.0);
  BondState s = makeBondState(c, nb, unit, unit, unit);
  for (const Segment& crack : cracks) breakCrossing(s, c, nb, crack);
  return std::move(s.intact);
}

std::vector<double> damageField(const std::vector<std::uint8_t>& intact, const PointCloud& c, const Neighbours& nb) {
  std::vector<double> phi(c.domain.size(), 0.0);
  for (std::size_t i = 0; i < c.domain.size(); ++i) {
    const std::size_t p = c.domain[i];
    std::size_t all = 0, broken = 0;
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      if (c.isVoid(nb.index[k])) continue;
      ++all;
      broken += intact[k] ? 0 : 1;
    }
    phi[i] = all ? static_cast<double>(broken) / static_cast<double>(all) : 1.0;
  }
  return phi;
}

std::size_t brokenPairs(const std::vector<std::uint8_t>& intact, const PointCloud& c, const Neighbours& nb) {
  std::size_t n = 0;
  for (std::size_t p = 0; p < c.size(); ++p)
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k)
      if (nb.index[k] > p && !intact[k] && !c.isVoid(p) && !c.isVoid(nb.index[k])) ++n;
  return n;
}

}  // namespace peristep
