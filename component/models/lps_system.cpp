#include "models/lps_system.hpp"

#include <algorithm>
#include <omp.h>

#include "models/lps_material.hpp"

namespace peristep {

std::vector<char> DofMap::thetaPoints() const {
  std::vector<char> t(theta.size());
  for (std::size_t p = 0; p < theta.size(); ++p) t[p] = theta[p] >= 0;
  return t;
}

DofMap numberDofs(const PointCloud& c, const Neighbours& nb) {
  std::vector<char> needsTheta(c.size(), 0);
  for (std::size_t p : c.domain) {
    needsTheta[p] = 1;
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) needsTheta[nb.index[k]] = 1;
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

}  // namespace

LpsSystem assembleLps(const PointCloud& c, const Neighbours& nb, const std::vector<double>& w,
                      const std::vector<double>& lambda, const std::vector<double>& mu, const DofMap& d) {
  const int threads = omp_get_max_threads();
  std::vector<CsrPiece> piecesA(static_cast<std::size_t>(threads)), piecesB(static_cast<std::size_t>(threads));
  const std::size_t n = c.size();

#pragma omp parallel num_threads(threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t first = n * t / static_cast<std::size_t>(threads);
    const std::size_t last = n * (t + 1) / static_cast<std::size_t>(threads);
    RowBuffer row;
    for (std::size_t p = first; p < last; ++p) {
      if (d.u[p] >= 0) {
        // Momentum balance at a domain point, DESIGN 5.1 / 000:(2.5):
        // -sum (lambda-mu)_pj K w (x_j-x_p)(theta_p+theta_j) - 8 sum mu_pj K w z z^T/|z|^2 (u_j-u_p) = f_p
        for (int a = 0; a < 2; ++a) {
          row.clear();
          double selfU[2] = {0.0, 0.0}, selfTheta = 0.0;
          for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
            const std::uint32_t q = nb.index[k];
            const double z[2] = {c.x[q] - c.x[p], c.y[q] - c.y[p]};
            const double r2 = z[0] * z[0] + z[1] * z[1];
            const double Kw = lpsKernel(std::sqrt(r2), c.delta) * w[k];
            const double dil = (harmonicMean(lambda[p], lambda[q]) - harmonicMean(mu[p], mu[q])) * Kw * z[a];
            const double shear = 8.0 * harmonicMean(mu[p], mu[q]) * Kw * z[a] / r2;
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
          piecesA[t].append(row.unknown);
          piecesB[t].append(row.prescribed);
        }
      }
      if (d.theta[p] >= 0) {
        // Nonlocal dilatation, 000:(3.2): theta_p - sum K w (x_j-x_p).(u_j-u_p) = 0.
        row.clear();
        double selfU[2] = {0.0, 0.0};
        for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
          const std::uint32_t q = nb.index[k];
          const double z[2] = {c.x[q] - c.x[p], c.y[q] - c.y[p]};
          const double Kw = lpsKernel(std::hypot(z[0], z[1]), c.delta) * w[k];
          for (int b = 0; b < 2; ++b) {
            addU(row, d, q, b, -Kw * z[b]);
            selfU[b] += Kw * z[b];
          }
        }
        addU(row, d, p, 0, selfU[0]);
        addU(row, d, p, 1, selfU[1]);
        row.unknown.emplace_back(d.theta[p], 1.0);
        piecesA[t].append(row.unknown);
        piecesB[t].append(row.prescribed);
      }
    }
  }
  return {concatenate(piecesA, d.size), concatenate(piecesB, 2 * static_cast<std::int64_t>(n))};
}

}  // namespace peristep
