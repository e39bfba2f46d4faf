#include "quadrature/optimization_weights.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "core/parallel_errors.hpp"

namespace peristep {
namespace {

double doubleFactorial(int n) {  // n!!, with (-1)!! = 0!! = 1
  double r = 1.0;
  for (int k = n; k > 1; k -= 2) r *= k;
  return r;
}

// int_0^{2pi} cos^a t sin^b t dt: zero unless both powers are even.
double angularIntegral(int a, int b) {
  if (a % 2 != 0 || b % 2 != 0) return 0.0;
  return 2.0 * std::numbers::pi * doubleFactorial(a - 1) * doubleFactorial(b - 1) / doubleFactorial(a + b);
}

// Constraint matrix of one neighbourhood in coordinates scaled by delta (well conditioned for any h).
Eigen::MatrixXd constraintMatrix(const PointCloud& c, const Neighbours& nb, std::size_t p) {
  const auto& mono = momentMonomials();
  const std::size_t m = nb.end(p) - nb.begin(p);
  Eigen::MatrixXd A(static_cast<Eigen::Index>(kMomentCount), static_cast<Eigen::Index>(m));
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t q = nb.index[nb.begin(p) + k];
    const double z1 = (c.x[q] - c.x[p]) / c.delta, z2 = (c.y[q] - c.y[p]) / c.delta;
    const double r3 = std::pow(std::hypot(z1, z2), 3);
    for (std::size_t r = 0; r < kMomentCount; ++r)
      A(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) =
          std::pow(z1, mono[r].a) * std::pow(z2, mono[r].b) / r3;
  }
  return A;
}

Eigen::VectorXd scaledMoments() {
  Eigen::VectorXd b(static_cast<Eigen::Index>(kMomentCount));
  for (std::size_t r = 0; r < kMomentCount; ++r) b(static_cast<Eigen::Index>(r)) = exactMoment(momentMonomials()[r], 1.0);
  return b;
}

// Key of a neighbourhood's shape: its offsets rounded to 1e-7 h, in neighbour order.
struct ShapeHash {
  std::size_t operator()(const std::vector<long long>& v) const {
    std::size_t s = v.size();
    for (long long x : v) s ^= std::hash<long long>{}(x) + 0x9e3779b97f4a7c15ULL + (s << 6) + (s >> 2);
    return s;
  }
};

}  // namespace

const std::array<Monomial, kMomentCount>& momentMonomials() {
  static const std::array<Monomial, kMomentCount> list = [] {
    std::array<Monomial, kMomentCount> l{};
    std::size_t k = 0;
    for (int degree = 2; degree <= 5; ++degree)
      for (int a = degree; a >= 0; --a) l[k++] = {a, degree - a};
    return l;
  }();
  return list;
}

double exactMoment(Monomial m, double delta) {
  const int d = m.a + m.b;
  return std::pow(delta, d - 1) / (d - 1) * angularIntegral(m.a, m.b);
}

std::vector<double> optimizationWeights(const PointCloud& c, const Neighbours& nb, const std::vector<char>& active) {
  // Group the active rows by neighbourhood shape so that a lattice solves one small problem.
  std::unordered_map<std::vector<long long>, std::size_t, ShapeHash> shapes;
  std::vector<std::size_t> representative;  // one row per shape
  std::vector<std::size_t> shapeOf(c.size(), 0);
  std::vector<long long> key;
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (!active[p]) continue;
    key.clear();
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      const std::uint32_t q = nb.index[k];
      key.push_back(std::llround((c.x[q] - c.x[p]) / c.h * 1e7));
      key.push_back(std::llround((c.y[q] - c.y[p]) / c.h * 1e7));
    }
    const auto [it, fresh] = shapes.try_emplace(key, representative.size());
    if (fresh) representative.push_back(p);
    shapeOf[p] = it->second;
  }

  const Eigen::VectorXd b = scaledMoments();
  const double area = c.delta * c.delta;  // w = delta^2 * (weights in scaled coordinates)
  std::vector<Eigen::VectorXd> shapeWeights(representative.size());
  ParallelErrors errors;  // the dense solves allocate
#pragma omp parallel for schedule(dynamic, 16)
  for (std::ptrdiff_t s = 0; s < static_cast<std::ptrdiff_t>(representative.size()); ++s)
    errors.capture([&] {
      const std::size_t p = representative[static_cast<std::size_t>(s)];
      if (nb.end(p) == nb.begin(p)) return;  // an isolated point has no quadrature
      const Eigen::MatrixXd A = constraintMatrix(c, nb, p);
      shapeWeights[static_cast<std::size_t>(s)] = area * A.completeOrthogonalDecomposition().solve(b);
    });
  errors.rethrow();

  std::vector<double> w(nb.bonds(), 0.0);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ps = 0; ps < static_cast<std::ptrdiff_t>(c.size()); ++ps) {
    const auto p = static_cast<std::size_t>(ps);
    if (!active[p] || nb.end(p) == nb.begin(p)) continue;
    const Eigen::VectorXd& ws = shapeWeights[shapeOf[p]];
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) w[k] = ws(static_cast<Eigen::Index>(k - nb.begin(p)));
  }
  return w;
}

double constraintError(const PointCloud& c, const Neighbours& nb, const std::vector<double>& w, std::size_t p) {
  // Compared in coordinates scaled by delta, so that every degree counts alike.
  const Eigen::VectorXd b = scaledMoments();
  const Eigen::MatrixXd A = constraintMatrix(c, nb, p);
  const auto m = static_cast<Eigen::Index>(nb.end(p) - nb.begin(p));
  const Eigen::Map<const Eigen::VectorXd> wp(w.data() + nb.begin(p), m);
  return (A * wp / (c.delta * c.delta) - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

}  // namespace peristep
