#include "models/lps_system.hpp"

#include <algorithm>
#include <cmath>
#include <omp.h>
#include <stdexcept>

#include "core/parallel_errors.hpp"
#include "models/lps_material.hpp"

namespace peristep {

DofMap numberDofs(const PointCloud& c, const Neighbours& nb) {
  std::vector<char> needsTheta(c.size(), 0);
  for (std::size_t p : c.domain) {
    needsTheta[p] = 1;
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k)
      if (!c.isVoid(nb.index[k])) needsTheta[nb.index[k]] = 1;
  }
  DofMap d;
  d.u.assign(c.size(), -1);
  d.theta.assign(c.size(), -1);
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (c.inDomain(p)) {
      d.u[p] = d.size;
      d.size += 2;
    }
    if (needsTheta[p]) d.theta[p] = d.size++;
  }
  return d;
}

namespace {

// One row under construction: (column, value) pairs for the unknown and the prescribed parts.
struct RowBuffer {
  std::vector<std::pair<std::int64_t, double>> unknown, prescribed;
  void clear() {
    unknown.clear();
    prescribed.clear();
  }
};

// Rows of a contiguous range of points, in CSR pieces that are concatenated afterwards.
struct CsrPiece {
  std::vector<std::int64_t> rowLength;
  std::vector<std::int64_t> col;
  std::vector<double> value;

  void append(std::vector<std::pair<std::int64_t, double>>& row) {
    std::sort(row.begin(), row.end());
    rowLength.push_back(static_cast<std::int64_t>(row.size()));
    for (const auto& [c, v] : row) {
      col.push_back(c);
      value.push_back(v);
    }
  }
};

CsrMatrix concatenate(std::vector<CsrPiece>& pieces, std::int64_t cols) {
  CsrMatrix m;
  m.cols = cols;
  for (CsrPiece& piece : pieces) {
    for (std::int64_t len : piece.rowLength) m.rowStart.push_back(m.rowStart.back() + len);
    m.col.insert(m.col.end(), piece.col.begin(), piece.col.end());
    m.value.insert(m.value.end(), piece.value.begin(), piece.value.end());
    piece = CsrPiece{};  // release memory early
  }
  m.rows = static_cast<std::int64_t>(m.rowStart.size()) - 1;
  return m;
}

// Adds a coefficient of displacement component `comp` of point q to the unknown or prescribed part.
void addU(RowBuffer& row, const DofMap& d, std::size_t q, int comp, double v) {
  if (d.u[q] >= 0)
    row.unknown.emplace_back(d.u[q] + comp, v);
  else
    row.prescribed.emplace_back(2 * static_cast<std::int64_t>(q) + comp, v);
}

// Free-surface geometry of one point, 000:(3.21)-(3.22): the correction tensor M (pseudo-inverse when
// singular, e.g. an isolated point) and the outward normal n with its tangent t.
struct SurfaceFrame {
  double M[2][2] = {{1, 0}, {0, 1}};
  double n[2] = {0, 0}, t[2] = {0, 0};
  bool broken = false;   // any broken bond at this point
  bool neumann = false;  // the free-surface terms of 000:(3.19) apply (see surfaceEndsInHorizon)
};

bool bondIntact(const Neighbours& nb, const std::vector<std::uint8_t>& intact, std::uint32_t j, std::uint32_t k) {
  const auto first = nb.index.begin() + static_cast<std::ptrdiff_t>(nb.begin(j));
  const auto last = nb.index.begin() + static_cast<std::ptrdiff_t>(nb.end(j));
  const auto it = std::lower_bound(first, last, k);  // rows are sorted
  return it != last && *it == k && intact[static_cast<std::size_t>(it - nb.index.begin())];
}

// True when a broken neighbour k of p is reached from p in two intact bonds p-j-k: the free surface
// that cut p-k ends inside p's horizon (a crack tip, a ligament). The terms of 000:(3.19) replace the
// missing bonds by the traction-free continuation of a flat surface with a unique projection (000
// Sec. 2.3); within delta of a crack tip there is none, and there they are a force proportional to a
// dilatation that averages the tip singularity, O(delta^(-3/2)) on O(delta^2) of area: a net force
// O(sqrt(delta)) at the tip that caps the Test 3 rate near 1/2 (nu = 0.3: 0.75, 0.62, 0.56 over
// pi/16 ... pi/128). Such points keep the intact bonds and the corrected dilatation 000:(3.20) only,
// whose pairwise antisymmetric forces exert no net force (rates 1.17, 1.18, 1.18; see
// docs/decisions/0017-free-surface-terms-near-tips.md).
bool surfaceEndsInHorizon(const PointCloud& c, const Neighbours& nb, const std::vector<std::uint8_t>& intact,
                          std::size_t p) {
  for (std::size_t kb = nb.begin(p); kb < nb.end(p); ++kb) {
    const std::uint32_t k = nb.index[kb];
    if (intact[kb] || c.isVoid(k)) continue;  // no bond ever reaches a Void point
    for (std::size_t jb = nb.begin(p); jb < nb.end(p); ++jb)
      if (intact[jb] && bondIntact(nb, intact, nb.index[jb], k)) return true;
  }
  return false;
}

SurfaceFrame surfaceFrame(const PointCloud& c, const Neighbours& nb, const std::vector<double>& w,
                          const std::vector<std::uint8_t>* intact, std::size_t p) {
  SurfaceFrame f;
  if (!intact) return f;
  double S[2][2] = {{0, 0}, {0, 0}}, m[2] = {0, 0};
  for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
    if (!(*intact)[k]) {
      f.broken = true;
      continue;
    }
    const std::uint32_t q = nb.index[k];
    const double z[2] = {c.x[q] - c.x[p], c.y[q] - c.y[p]};
    const double Kw = lpsKernel(std::hypot(z[0], z[1]), c.delta) * w[k];
    for (int a = 0; a < 2; ++a) {
      m[a] += z[a] * w[k];
      for (int b = 0; b < 2; ++b) S[a][b] += Kw * z[a] * z[b];
    }
  }
  if (!f.broken) return f;  // full neighbourhood: M = I exactly (the weights integrate K z z^T)
  // Symmetric 2x2 pseudo-inverse; S is O(1) (it is I for a full neighbourhood).
  const double tr = S[0][0] + S[1][1], det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
  const double disc = std::sqrt(std::max(0.0, 0.25 * tr * tr - det));
  const double l1 = 0.5 * tr + disc, l2 = 0.5 * tr - disc;
  double v1[2] = {S[0][1], l1 - S[0][0]};
  if (std::hypot(v1[0], v1[1]) < 1e-14) v1[0] = 1, v1[1] = 0;
  const double nv = std::hypot(v1[0], v1[1]);
  v1[0] /= nv, v1[1] /= nv;
  const double v2[2] = {-v1[1], v1[0]};
  const double tol = 1e-10;
  const double i1 = l1 > tol ? 1 / l1 : 0, i2 = l2 > tol ? 1 / l2 : 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) f.M[a][b] = i1 * v1[a] * v1[b] + i2 * v2[a] * v2[b];
  const double mn = std::hypot(m[0], m[1]);
  if (mn > 1e-12 * c.delta * c.delta * c.delta) {  // 000:(3.22): n points away from the intact bonds
    f.n[0] = -m[0] / mn, f.n[1] = -m[1] / mn;
    f.t[0] = -f.n[1], f.t[1] = f.n[0];
  }
  f.neumann = !surfaceEndsInHorizon(c, nb, *intact, p);
  return f;
}

// The rows of point p (u_x, u_y, theta, those that are unknowns), each passed to emit(row index, row).
template <class Emit>
void pointRows(const PointCloud& c, const Neighbours& nb, const std::vector<double>& w,
               const std::vector<double>& lambda, const std::vector<double>& mu, const DofMap& d,
               const std::vector<std::uint8_t>* intact, std::size_t p, RowBuffer& row, Emit&& emit) {
  if (d.u[p] < 0 && d.theta[p] < 0) return;
  const auto gamma = [&](std::size_t k) { return intact ? static_cast<double>((*intact)[k]) : 1.0; };
  const SurfaceFrame frame = surfaceFrame(c, nb, w, intact, p);
  if (d.u[p] >= 0) {
    // Momentum balance at a domain point, 000:(3.19) with the sign of 000:(2.5) (DESIGN 5.1):
    //   sum_j K [ -(lambda-mu)_pj z (theta_p+theta_j) - 8 mu_pj z z^T/|z|^2 (u_j-u_p) ] w~_pj
    // + theta_p sum_j K [ -2(lambda-mu) z - 4(lambda+2mu) n (z.n)(z.t)^2/|z|^2
    //                     + 4 lambda n (z.n)^3/|z|^2 ] w^_pj = f_p,   z = x_j - x_p,
    // the second line only where a free surface crosses the whole horizon (frame.neumann).
    for (int a = 0; a < 2; ++a) {
      row.clear();
      double selfU[2] = {0.0, 0.0}, selfTheta = 0.0;
      for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
        const std::uint32_t q = nb.index[k];
        const double z[2] = {c.x[q] - c.x[p], c.y[q] - c.y[p]};
        const double r2 = z[0] * z[0] + z[1] * z[1];
        const double K = lpsKernel(std::sqrt(r2), c.delta);
        const double lam = harmonicMean(lambda[p], lambda[q]), m = harmonicMean(mu[p], mu[q]);
        const double g = gamma(k), Kw = K * w[k] * g, Kwb = K * w[k] * (1.0 - g);
        if (Kwb != 0.0 && frame.neumann) {
          const double zn = z[0] * frame.n[0] + z[1] * frame.n[1], zt = z[0] * frame.t[0] + z[1] * frame.t[1];
          selfTheta += Kwb * (-2.0 * (lam - m) * z[a] - 4.0 * (lam + 2.0 * m) * frame.n[a] * zn * zt * zt / r2 +
                              4.0 * lam * frame.n[a] * zn * zn * zn / r2);
        }
        if (c.isVoid(q)) continue;  // no unknowns there: only the free-surface term above
        const double dil = (lam - m) * Kw * z[a];
        const double shear = 8.0 * m * Kw * z[a] / r2;
        row.unknown.emplace_back(d.theta[q], -dil);
        selfTheta -= dil;
        for (int b = 0; b < 2; ++b) {
          addU(row, d, q, b, -shear * z[b]);
          selfU[b] += shear * z[b];
        }
      }
      row.unknown.emplace_back(d.u[p], selfU[0]);
      row.unknown.emplace_back(d.u[p] + 1, selfU[1]);
      row.unknown.emplace_back(d.theta[p], selfTheta);
      emit(d.u[p] + a, row);
    }
  }
  if (d.theta[p] >= 0) {
    // Corrected nonlocal dilatation, 000:(3.20): theta_p - sum K (x_j-x_p).M_p (u_j-u_p) w~ = 0.
    row.clear();
    double selfU[2] = {0.0, 0.0};
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      const std::uint32_t q = nb.index[k];
      if (c.isVoid(q)) continue;
      const double z[2] = {c.x[q] - c.x[p], c.y[q] - c.y[p]};
      const double Kw = lpsKernel(std::hypot(z[0], z[1]), c.delta) * w[k] * gamma(k);
      const double Mz[2] = {frame.M[0][0] * z[0] + frame.M[0][1] * z[1], frame.M[1][0] * z[0] + frame.M[1][1] * z[1]};
      for (int b = 0; b < 2; ++b) {
        addU(row, d, q, b, -Kw * Mz[b]);
        selfU[b] += Kw * Mz[b];
      }
    }
    addU(row, d, p, 0, selfU[0]);
    addU(row, d, p, 1, selfU[1]);
    row.unknown.emplace_back(d.theta[p], 1.0);
    emit(d.theta[p], row);
  }
}

}  // namespace

LpsSystem assembleLps(const PointCloud& c, const Neighbours& nb, const std::vector<double>& w,
                      const std::vector<double>& lambda, const std::vector<double>& mu, const DofMap& d,
                      const std::vector<std::uint8_t>* intact) {
  const int threads = omp_get_max_threads();
  std::vector<CsrPiece> piecesA(static_cast<std::size_t>(threads)), piecesB(static_cast<std::size_t>(threads));
  const std::size_t n = c.size();

  ParallelErrors errors;  // CsrPiece::append allocates: a bad_alloc must not leave the region
#pragma omp parallel num_threads(threads)
  errors.capture([&] {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t first = n * t / static_cast<std::size_t>(threads);
    const std::size_t last = n * (t + 1) / static_cast<std::size_t>(threads);
    RowBuffer row;
    for (std::size_t p = first; p < last; ++p)
      pointRows(c, nb, w, lambda, mu, d, intact, p, row, [&](std::int64_t, RowBuffer& r) {
        piecesA[t].append(r.unknown);
        piecesB[t].append(r.prescribed);
      });
  });
  errors.rethrow();
  return {concatenate(piecesA, d.size), concatenate(piecesB, 2 * static_cast<std::int64_t>(n))};
}

void reassembleLpsRows(const PointCloud& c, const Neighbours& nb, const std::vector<double>& w,
                       const std::vector<double>& lambda, const std::vector<double>& mu, const DofMap& d,
                       const std::vector<std::uint8_t>& intact, std::span<const std::size_t> points, LpsSystem& s) {
  const auto overwrite = [](CsrMatrix& m, std::int64_t r, std::vector<std::pair<std::int64_t, double>>& row) {
    std::sort(row.begin(), row.end());  // the order CsrPiece::append stores
    const auto first = static_cast<std::size_t>(m.rowStart[static_cast<std::size_t>(r)]);
    if (static_cast<std::size_t>(m.rowStart[static_cast<std::size_t>(r) + 1]) - first != row.size())
      throw std::logic_error("reassembleLpsRows: the sparsity pattern of a row changed");
    for (std::size_t k = 0; k < row.size(); ++k) m.value[first + k] = row[k].second;
  };
  ParallelErrors errors;
#pragma omp parallel
  errors.capture([&] {
    RowBuffer row;
#pragma omp for schedule(dynamic, 16)
    for (std::size_t i = 0; i < points.size(); ++i)
      pointRows(c, nb, w, lambda, mu, d, &intact, points[i], row, [&](std::int64_t r, RowBuffer& b) {
        overwrite(s.A, r, b.unknown);
        overwrite(s.B, r, b.prescribed);
      });
  });
  errors.rethrow();
}

}  // namespace peristep
