#include "linalg/gmres.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/blocked_sum.hpp"

namespace peristep {
namespace {

double norm(std::span<const double> v) {
  double s = 0;
  for (double a : v) s += a * a;
  return std::sqrt(s);
}

// C(:, 0:k)^T w for row-major C (stride `stride`).
std::vector<double> transposedProduct(const std::vector<double>& C, std::size_t stride, std::size_t k,
                                      std::span<const double> w) {
  return blockedSums(w.size(), k, [&](std::size_t i, double* p) {
    const double* row = &C[i * stride];
    for (std::size_t a = 0; a < k; ++a) p[a] += w[i] * row[a];
  });
}

// v += sign * M(:, 0:k) y for row-major M.
void addProduct(const std::vector<double>& M, std::size_t stride, const std::vector<double>& y, double sign,
                std::span<double> v) {
  const std::size_t n = v.size(), k = y.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const double* row = &M[i * stride];
    double s = 0;
    for (std::size_t a = 0; a < k; ++a) s += row[a] * y[a];
    v[i] += sign * s;
  }
}

}  // namespace

void RecycledDirections::forget() { count_ = pending_ = 0; }

void RecycledDirections::clear() {
  n_ = count_ = pending_ = 0;
  std::vector<double>().swap(z_);
  std::vector<double>().swap(c_);
  std::vector<double>().swap(gram_);
}

void RecycledDirections::reserve(std::size_t n) {
  if (n_ == n) return;
  clear();
  n_ = n;
  z_.assign(n * capacity_, 0.0);
  c_.assign(n * capacity_, 0.0);
  gram_.assign(capacity_ * capacity_, 0.0);
}

void RecycledDirections::refreshRow(std::size_t i, std::span<const std::int64_t> columns,
                                    std::span<const double> values, std::span<const double> scale) {
  if (count_ == 0) return;
  std::vector<double> fresh(count_, 0.0);
  for (std::size_t t = 0; t < columns.size(); ++t) {
    const auto j = static_cast<std::size_t>(columns[t]);
    const double a = values[t] * scale[j];
    const double* zj = &z_[j * capacity_];
    for (std::size_t k = 0; k < count_; ++k) fresh[k] += a * zj[k];
  }
  double* ci = &c_[i * capacity_];
  for (std::size_t k = 0; k < count_; ++k) fresh[k] *= scale[i];
  for (std::size_t a = 0; a < count_; ++a)
    for (std::size_t b = 0; b < count_; ++b) gram_[a * capacity_ + b] += fresh[a] * fresh[b] - ci[a] * ci[b];
  std::copy(fresh.begin(), fresh.end(), ci);
}

void RecycledDirections::stage(std::span<const double> z, std::span<const double> c) {
  const std::size_t k = count_ + pending_;
  if (k == capacity_) return;
  for (std::size_t i = 0; i < n_; ++i) {
    z_[i * capacity_ + k] = z[i];
    c_[i * capacity_ + k] = c[i];
  }
  ++pending_;
}

void RecycledDirections::commit() {
  // The Gram matrix's new columns: (C^T C)(a, k) for every a and the new k.
  const std::size_t first = count_, end = count_ + pending_;
  pending_ = 0;
  if (end == first) return;
  const std::vector<double> sums = blockedSums(n_, end * (end - first), [&](std::size_t i, double* p) {
    const double* row = &c_[i * capacity_];
    for (std::size_t k = first; k < end; ++k)
      for (std::size_t a = 0; a < end; ++a) p[(k - first) * end + a] += row[a] * row[k];
  });
  for (std::size_t k = first; k < end; ++k)
    for (std::size_t a = 0; a < end; ++a) gram_[a * capacity_ + k] = gram_[k * capacity_ + a] = sums[(k - first) * end + a];
  count_ = end;
}

GmresResult gmres(const CsrMatrix& A, LinearSolver& M, std::span<const double> b, std::span<double> x, double tol,
                  int maxIterations, int restart) {
  return gmres([&](std::span<const double> in, std::span<double> out) { A.multiply(in, out); },
               [&](std::span<const double> in, std::span<double> out) { M.precondition(in, out); }, b, x, tol,
               maxIterations, restart);
}

namespace {

// Least squares on the kept C through its Gram matrix, with directions the others repeat (eigenvalues below
// 1e-12 of the largest) left out: coeff = G^+ C^T w, and w loses its part in range(C).
class RangeProjection {
 public:
  // C (row-major, `stride` columns of which the first k are kept) and its Gram matrix C^T C.
  RangeProjection(const std::vector<double>& C, const std::vector<double>& gram, std::size_t k, std::size_t stride)
      : c_(C), k_(k), stride_(stride) {
    if (k == 0) return;
    Eigen::MatrixXd G(k, k);
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t c = 0; c < k; ++c) G(a, c) = gram[a * stride + c];
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(G);
    basis_ = eig.eigenvectors();
    inverse_ = eig.eigenvalues();
    const double largest = inverse_.maxCoeff();
    for (Eigen::Index a = 0; a < inverse_.size(); ++a) inverse_(a) = inverse_(a) > 1e-12 * largest ? 1.0 / inverse_(a) : 0.0;
  }

  void operator()(std::vector<double>& w, std::vector<double>& coeff) const {
    const std::vector<double> t = transposedProduct(c_, stride_, k_, w);
    const Eigen::VectorXd c = basis_ * inverse_.cwiseProduct(basis_.transpose() * Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(k_)));
    coeff.assign(c.data(), c.data() + k_);
    addProduct(c_, stride_, coeff, -1.0, w);
  }

 private:
  const std::vector<double>& c_;
  std::size_t k_, stride_;
  Eigen::MatrixXd basis_;
  Eigen::VectorXd inverse_;
};

// Modified Gram-Schmidt of w against V[0..j] into column j of H, and V[j + 1] = w / |w|.
void orthogonalize(std::vector<double>& w, std::vector<std::vector<double>>& V, std::vector<std::vector<double>>& H,
                   std::size_t j) {
  const std::size_t n = w.size();
  for (std::size_t i = 0; i <= j; ++i) {
    double h = 0;
    for (std::size_t q = 0; q < n; ++q) h += w[q] * V[i][q];
    H[i][j] = h;
    for (std::size_t q = 0; q < n; ++q) w[q] -= h * V[i][q];
  }
  H[j + 1][j] = norm(w);
  if (H[j + 1][j] > 0)
    for (std::size_t q = 0; q < n; ++q) V[j + 1][q] = w[q] / H[j + 1][j];
}

// Column j of H through the earlier Givens rotations and a new one that zeroes H[j + 1][j]; g follows.
void rotate(std::vector<std::vector<double>>& H, std::vector<double>& cs, std::vector<double>& sn, std::vector<double>& g,
            std::size_t j) {
  for (std::size_t i = 0; i < j; ++i) {
    const double h = cs[i] * H[i][j] + sn[i] * H[i + 1][j];
    H[i + 1][j] = -sn[i] * H[i][j] + cs[i] * H[i + 1][j];
    H[i][j] = h;
  }
  const double d = std::hypot(H[j][j], H[j + 1][j]);
  cs[j] = d > 0 ? H[j][j] / d : 1.0;
  sn[j] = d > 0 ? H[j + 1][j] / d : 0.0;
  H[j][j] = d;
  H[j + 1][j] = 0;
  g[j + 1] = -sn[j] * g[j];
  g[j] = cs[j] * g[j];
}

// y with H y = g, H upper triangular of size j.
std::vector<double> backSubstitute(const std::vector<std::vector<double>>& H, const std::vector<double>& g, std::size_t j) {
  std::vector<double> y(j);
  for (std::size_t i = j; i-- > 0;) {
    double s = g[i];
    for (std::size_t q = i + 1; q < j; ++q) s -= H[i][q] * y[q];
    y[i] = s / H[i][i];
  }
  return y;
}

}  // namespace

GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, std::span<const double> b,
                  std::span<double> x, double tol, int maxIterations, int restart, RecycledDirections* recycled) {
  const std::size_t n = b.size(), m = static_cast<std::size_t>(restart);
  GmresResult result;
  const double bnorm = norm(b);
  if (bnorm == 0) {
    std::fill(x.begin(), x.end(), 0.0);
    result.converged = true;
    return result;
  }
  RecycledDirections none(0);
  RecycledDirections& kept = recycled ? *recycled : none;
  kept.reserve(n);
  const std::size_t k = kept.count_, stride = kept.capacity_;
  const RangeProjection project(kept.c_, kept.gram_, k, stride);

  // The Krylov vectors are allocated as the iterations reach them: a solve here takes a few iterations of the
  // 40 a restart allows, and 81 vectors of 266k unknowns (172 MB) would raise the run's peak memory.
  std::vector<std::vector<double>> V(1, std::vector<double>(n)), Z;
  std::vector<std::vector<double>> H(m + 1, std::vector<double>(m, 0.0)), B(m);
  std::vector<double> cs(m), sn(m), g(m + 1), w(n), r(n), coeff;
  const auto residual = [&] {
    apply(x, r);
    for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
    return norm(r);
  };
  const auto converged = [&](double beta) {
    result.relativeResidual = beta / bnorm;
    return result.converged = result.relativeResidual <= tol;
  };

  while (result.iterations < maxIterations) {
    double beta = residual();
    if (converged(beta)) break;
    if (k > 0) {
      project(r, coeff);
      addProduct(kept.z_, stride, coeff, 1.0, x);
      beta = norm(r);
      // The kept directions alone may do: then check the true residual.
      if (beta / bnorm <= tol) {
        beta = residual();
        if (converged(beta)) break;
      }
    }
    for (std::size_t i = 0; i < n; ++i) V[0][i] = r[i] / beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    std::size_t j = 0;
    for (; j < m && result.iterations < maxIterations; ++j) {
      ++result.iterations;
      if (Z.size() == j) {
        Z.emplace_back(n);
        V.emplace_back(n);
      }
      precondition(V[j], Z[j]);  // right preconditioning: z_j = M^{-1} v_j
      apply(Z[j], w);
      kept.stage(Z[j], w);
      // A (z_j - Z_kept B_j) = w - C B_j: the Krylov vectors stay orthogonal to range(C).
      if (k > 0) project(w, B[j]);
      orthogonalize(w, V, H, j);
      rotate(H, cs, sn, g, j);
      if (std::abs(g[j + 1]) / bnorm <= tol) {
        ++j;
        break;
      }
    }
    // x += sum_j y_j (z_j - Z_kept B_j)
    const std::vector<double> y = backSubstitute(H, g, j);
    for (std::size_t i = 0; i < j; ++i)
      for (std::size_t q = 0; q < n; ++q) x[q] += y[i] * Z[i][q];
    if (k > 0) {
      std::vector<double> d(k, 0.0);
      for (std::size_t i = 0; i < j; ++i)
        for (std::size_t a = 0; a < k; ++a) d[a] += B[i][a] * y[i];
      addProduct(kept.z_, stride, d, -1.0, x);
    }
  }
  if (!result.converged) converged(residual());
  kept.commit();
  return result;
}

}  // namespace peristep
