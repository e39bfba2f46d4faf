#include "linalg/crack_zone_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "core/errors.hpp"
#include "core/memory.hpp"
#include "linalg/metis_ordering.hpp"

namespace peristep {
namespace {

// r = b - A x and the componentwise backward error max_i |r_i| / (|A| |x| + |b|)_i (Oettli-Prager):
// the rows of A differ in scale by 20 orders, so a norm of r would see only the largest ones.
double backwardError(const CsrMatrix& A, std::span<const double> b, std::span<const double> x, std::vector<double>& r) {
  double worst = 0;
#pragma omp parallel for schedule(static) reduction(max : worst)
  for (std::int64_t i = 0; i < A.rows; ++i) {
    double ax = 0, scale = 0;
    for (std::int64_t k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      const double t = A.value[k] * x[static_cast<std::size_t>(A.col[k])];
      ax += t;
      scale += std::abs(t);
    }
    const auto row = static_cast<std::size_t>(i);
    r[row] = b[row] - ax;
    scale += std::abs(b[row]);
    // A non-finite entry of x (single-precision factors can overflow) must not pass: NaN loses every max.
    if (!std::isfinite(r[row]) || !std::isfinite(scale))
      worst = std::numeric_limits<double>::infinity();
    else if (scale > 0)
      worst = std::max(worst, std::abs(r[row]) / scale);
  }
  return worst;
}

// Horizons around the rows changed beyond the zone that the patch correction takes in (one or four cost zones
// and substitutions at full size, three, four or six at h = 4 um), and its largest size as a share of the
// unknowns: at h = 8 um patches of ~1300 of some 20,000 unknowns cost more in LUs and products than they saved
// in substitutions (docs/decisions/0010-patch-correction.md).
constexpr int kPatchHorizons = 2;
constexpr std::size_t kPatchShare = 20;

}  // namespace

std::vector<std::int64_t> CrackZoneSolver::zoneUnknowns() const {
  std::vector<std::uint8_t> inZone(dofs_.u.size(), 0);
  for (const auto* points : {&core_, &extra_})
    for (std::size_t p : *points) {
      inZone[p] = 1;
      for (std::size_t k = nb_.begin(p); k < nb_.end(p); ++k) inZone[nb_.index[k]] = 1;
    }
  std::vector<std::int64_t> unknowns;
  for (std::size_t p = 0; p < inZone.size(); ++p)
    if (inZone[p]) dofs_.forEachRow(p, [&](std::int64_t r) { unknowns.push_back(r); });
  std::sort(unknowns.begin(), unknowns.end());
  return unknowns;
}

std::vector<std::size_t> CrackZoneSolver::planCore(const std::vector<double>& priority, double threshold,
                                                   std::size_t budget) const {
  const std::size_t n = dofs_.u.size();
  std::vector<std::size_t> order;
  for (std::size_t p = 0; p < n; ++p)
    if (priority[p] >= threshold) order.push_back(p);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return priority[a] > priority[b]; });
  const auto unknownsOf = [&](std::size_t p) {
    return static_cast<std::size_t>(dofs_.u[p] >= 0 ? 2 : 0) + static_cast<std::size_t>(dofs_.theta[p] >= 0 ? 1 : 0);
  };
  std::vector<std::uint8_t> core(n, 0), zone(n, 0);
  std::vector<std::size_t> stamp(n, 0);
  std::size_t unknowns = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t seed = order[i];
    // The zone unknowns that seed's core points would add (stamped so that each counts once).
    std::size_t extra = 0;
    const auto visitCore = [&](auto&& f) {
      f(seed);
      for (std::size_t k = nb_.begin(seed); k < nb_.end(seed); ++k) f(static_cast<std::size_t>(nb_.index[k]));
    };
    const auto zoneAround = [&](std::size_t c, auto&& g) {
      g(c);
      for (std::size_t k = nb_.begin(c); k < nb_.end(c); ++k) g(static_cast<std::size_t>(nb_.index[k]));
    };
    visitCore([&](std::size_t c) {
      if (core[c]) return;
      zoneAround(c, [&](std::size_t z) {
        if (zone[z] || stamp[z] == i + 1) return;
        stamp[z] = i + 1;
        extra += unknownsOf(z);
      });
    });
    if (unknowns + extra > budget) break;
    unknowns += extra;
    visitCore([&](std::size_t c) {
      if (core[c]) return;
      core[c] = 1;
      zoneAround(c, [&](std::size_t z) { zone[z] = 1; });
    });
  }
  std::vector<std::size_t> result;
  for (std::size_t p = 0; p < n; ++p)
    if (core[p]) result.push_back(p);
  return result;
}

void CrackZoneSolver::factorize(const CsrMatrix& A, std::vector<std::size_t> corePoints,
                                std::vector<std::size_t> extraPoints) {
  kept_.clear();  // they were preconditioned by the old factors
  patch_.clear();
  beyondRows_.clear();
  isBeyondRow_.assign(static_cast<std::size_t>(dofs_.size), 0);
  core_ = std::move(corePoints);
  extra_ = std::move(extraPoints);
  zone_ = zoneUnknowns();
  zoneIndex_.assign(static_cast<std::size_t>(dofs_.size), -1);
  for (std::size_t i = 0; i < zone_.size(); ++i) zoneIndex_[static_cast<std::size_t>(zone_[i])] = static_cast<std::int32_t>(i);
  // The rows of the extra points outside the core stay with GMRES: when such a point's last bond breaks, only
  // its spring (1e-8 of a bond) holds it, and with that change in the dense solver neither refinement nor 200
  // GMRES iterations reached 1e-13 for some points of the test plate (tests/crack_zone_solver_test.cpp).
  takesUp_.assign(zone_.size(), 1);
  for (std::size_t p : extra_)
    if (!std::binary_search(core_.begin(), core_.end(), p))
      dofs_.forEachRow(p, [&](std::int64_t r) {
        takesUp_[static_cast<std::size_t>(zoneIndex_[static_cast<std::size_t>(r)])] = 0;
      });
  scale_.assign(static_cast<std::size_t>(A.rows), 1.0);
  for (std::int64_t r = 0; r < A.rows; ++r)
    for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k)
      if (A.col[k] == r && A.value[k] != 0.0) scale_[static_cast<std::size_t>(r)] = 1.0 / std::sqrt(std::abs(A.value[k]));
  // The last zone's matrix and dense solver go first: the sparse factorization sets the run's peak memory.
  freeStorage(factored_);
  dense_.release();
#if defined(__GLIBC__)
  // Freed blocks inside the heap stay resident (Krylov vectors, rows, the last zone's arrays); return them
  // before the factorization's peak (h = 2 um, f = 0.8: run peak 3125 -> 3045 MiB).
  malloc_trim(0);
#endif
  if (dissection_.empty()) dissection_ = dissectionOrder();
  sparse_.factorize(A, scale_, zone_, pivotOrder());
  factored_ = A.value;
  dense_.reset(sparse_.takeSchurComplement());
  reduced_.resize(zone_.size());
  xZone_.resize(zone_.size());
}

std::vector<std::size_t> CrackZoneSolver::dissectionOrder() const {
  const std::size_t n = dofs_.u.size();
  std::vector<std::int32_t> vertex(n, -1);
  std::vector<std::size_t> points;
  for (std::size_t p = 0; p < n; ++p) {
    if (dofs_.u[p] < 0 && dofs_.theta[p] < 0) continue;  // no unknowns
    vertex[p] = static_cast<std::int32_t>(points.size());
    points.push_back(p);
  }
  std::vector<std::int32_t> xadj{0}, adjacency;
  for (std::size_t p : points) {
    for (std::size_t k = nb_.begin(p); k < nb_.end(p); ++k)
      if (vertex[nb_.index[k]] >= 0) adjacency.push_back(vertex[nb_.index[k]]);
    xadj.push_back(static_cast<std::int32_t>(adjacency.size()));
  }
  const std::vector<std::int32_t> rank = nestedDissection(std::move(xadj), std::move(adjacency));
  std::vector<std::size_t> order(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) order[static_cast<std::size_t>(rank[v])] = points[v];
  return order;
}

std::vector<std::int32_t> CrackZoneSolver::pivotOrder() const {
  // The points outside the zone in the order of the nested dissection of all points, then the zone. Leaving
  // the zone's points out of an elimination order only removes fill paths among the others; the zone, eliminated
  // last, separates what it cuts. One METIS call per zone cost 0.83 s of its ~9 s at h = 2 um; the whole-graph
  // order gives 3-5% more factor entries and the same crack histories
  // (docs/decisions/0007-one-nested-dissection-and-column-counts.md).
  std::vector<std::int32_t> position(static_cast<std::size_t>(dofs_.size), -1);
  std::int32_t next = 0;
  for (std::size_t p : dissection_) {
    bool outside = false;
    dofs_.forEachRow(p, [&](std::int64_t r) { outside = outside || zoneIndex_[static_cast<std::size_t>(r)] < 0; });
    if (outside) dofs_.forEachRow(p, [&](std::int64_t r) { position[static_cast<std::size_t>(r)] = next++; });
  }
  for (std::int64_t r : zone_) position[static_cast<std::size_t>(r)] = next++;
  require(next == static_cast<std::int32_t>(dofs_.size), "crack zone: ordering misses unknowns");
  return position;
}

CrackZoneSolver::RowChange CrackZoneSolver::rowChange(const CsrMatrix& A, std::int64_t row,
                                                     std::vector<std::int32_t>& columns,
                                                     std::vector<double>& change) const {
  columns.clear();
  change.clear();
  RowChange result = RowChange::None;
  const auto r = static_cast<std::size_t>(row);
  for (auto k = static_cast<std::size_t>(A.rowStart[r]); k < static_cast<std::size_t>(A.rowStart[r + 1]); ++k) {
    const double d = A.value[k] - factored_[k];
    const auto col = static_cast<std::size_t>(A.col[k]);
    const std::int32_t c = zoneIndex_[col];
    if (c < 0) {
      if (d != 0.0) result = RowChange::BeyondZone;
      continue;
    }
    if (d != 0.0 && result == RowChange::None) result = RowChange::InZone;
    columns.push_back(c);
    change.push_back(scale_[r] * d * scale_[col]);
  }
  return result;
}

void CrackZoneSolver::setZoneRow(const CsrMatrix& A, std::int64_t row, std::vector<std::int32_t>& columns,
                                 std::vector<double>& change, std::size_t& beyond) {
  const RowChange kind = rowChange(A, row, columns, change);
  const std::int32_t i = zoneIndex_[static_cast<std::size_t>(row)];
  const bool takesUp = i >= 0 && takesUp_[static_cast<std::size_t>(i)];
  if (takesUp) dense_.setRow(static_cast<std::size_t>(i), columns, change);
  if (kind == RowChange::BeyondZone || (kind == RowChange::InZone && !takesUp)) {
    ++beyond;
    if (!isBeyondRow_[static_cast<std::size_t>(row)]) {
      isBeyondRow_[static_cast<std::size_t>(row)] = 1;
      beyondRows_.push_back(row);
    }
  }
}

std::size_t CrackZoneSolver::update(const CsrMatrix& A, std::span<const std::size_t> points) {
  require(!factored_.empty(), "crack zone: update before factorize");
  std::vector<std::int32_t> columns;
  std::vector<double> change;
  std::size_t beyond = 0;
  for (std::size_t p : points)
    dofs_.forEachRow(p, [&](std::int64_t r) {
      setZoneRow(A, r, columns, change, beyond);
      const auto b = static_cast<std::size_t>(A.rowStart[r]), e = static_cast<std::size_t>(A.rowStart[r + 1]);
      kept_.refreshRow(static_cast<std::size_t>(r), std::span(A.col).subspan(b, e - b),
                       std::span(A.value).subspan(b, e - b), scale_);
    });
  return beyond;
}

void CrackZoneSolver::restoreDense(const CsrMatrix& base, std::span<const std::size_t> correctionOrder,
                                   std::span<const std::size_t> correctionBlocks, const CsrMatrix& A) {
  std::vector<std::int32_t> columns;
  std::vector<double> change;
  bool baseChanged = false;
  for (std::size_t i = 0; i < zone_.size(); ++i)
    if (takesUp_[i] && rowChange(base, zone_[i], columns, change) != RowChange::None) {
      baseChanged = true;
      dense_.setRow(i, columns, change);
    }
  if (baseChanged) dense_.refactorize();
  std::vector<std::uint8_t> done(zone_.size(), 0);
  const auto set = [&](std::size_t i) {
    rowChange(A, zone_[i], columns, change);
    dense_.setRow(i, columns, change);
    done[i] = 1;
  };
  for (std::size_t i : correctionOrder) {
    require(i < zone_.size(), "crack zone: corrupt correction order");
    set(i);
  }
  dense_.replayCorrection(correctionBlocks);
  for (std::size_t i = 0; i < zone_.size(); ++i)
    if (takesUp_[i] && !done[i]) set(i);
}

void CrackZoneSolver::solveScaled(std::span<const double> b, std::span<double> y) {
  ++substitutions_;
  if (zone_.empty()) {
    sparse_.solve(b, y);
    return;
  }
  sparse_.condense(b, reduced_);
  dense_.solve(reduced_, xZone_);
  sparse_.expand(xZone_, y);
}

void CrackZoneSolver::solveOnce(std::span<const double> b, std::span<double> x) {
  // (D A D) (D^-1 x) = D b
  std::vector<double> scaled(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) scaled[i] = scale_[i] * b[i];
  solveScaled(scaled, x);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] *= scale_[i];
}

GmresResult CrackZoneSolver::solveIterative(const CsrMatrix& A, std::span<const double> b, std::span<double> x,
                                            double tol, int maxIterations, int restart, bool recycle) {
  const std::size_t n = b.size();
  std::vector<double> bs(n), y(n), t(n);
  for (std::size_t i = 0; i < n; ++i) {
    bs[i] = scale_[i] * b[i];
    y[i] = x[i] / scale_[i];
  }
  const auto apply = [&](std::span<const double> in, std::span<double> out) {
    for (std::size_t i = 0; i < n; ++i) t[i] = scale_[i] * in[i];
    A.multiply(t, out);
    for (std::size_t i = 0; i < n; ++i) out[i] *= scale_[i];
  };
  patch_.build(A, scale_, beyondRows_, kPatchHorizons, n / kPatchShare);
  const PatchCorrection::Solve zoneSolve = [&](std::span<const double> in, std::span<double> out) {
    solveScaled(in, out);
  };
  const auto precondition = [&](std::span<const double> in, std::span<double> out) {
    patch_.apply(in, out, zoneSolve);
  };
  const GmresResult result = gmres(apply, precondition, bs, y, tol, maxIterations, restart, recycle ? &kept_ : nullptr);
  // Single-precision factors of a nearly singular matrix can overflow: x then keeps the last finite solution.
  if (std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); }))
    for (std::size_t i = 0; i < n; ++i) x[i] = scale_[i] * y[i];
  return result;
}

bool CrackZoneSolver::solve(const CsrMatrix& A, std::span<const double> b, std::span<double> x, double tol,
                            double settleTol, double* lastChange) {
  // Refinement in double against the current A, from the caller's x (the last solution: after a few breaks
  // its residual is small, and one solve with single-precision factors, which multiplies the backward
  // error by ~1e-6, then often suffices; h = 8 um: 2.4 solves per call instead of 3 from x = 0).
  const int kMaxSteps = sparse_.precision() == FactorPrecision::Single ? 8 : 5;
  std::vector<double> r(b.size()), dx(b.size());
  for (int steps = 0;; ++steps) {
    const double error = backwardError(A, b, x, r);
    if (error <= tol) {
      if (lastChange) *lastChange = 0;
      return true;
    }
    if (steps > 0 && error <= settleTol) return true;
    if (steps == kMaxSteps || !std::isfinite(error)) return false;
    solveOnce(r, dx);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += dx[i];
    if (lastChange) {
      *lastChange = 0;
      for (std::int64_t row : dofs_.u)
        if (row >= 0)
          *lastChange = std::max({*lastChange, std::abs(dx[static_cast<std::size_t>(row)]),
                                  std::abs(dx[static_cast<std::size_t>(row) + 1])});
    }
  }
}

}  // namespace peristep
