// Sparse pseudo-spectral projection of host/sampling (Constantine-Eldred-Phipps 2012): the surrogate's
// variance, a sum of squared coefficients, is exact for low-degree polynomials in 2-3 variables and
// stays >= 0 where the direct quadrature estimate of the variance goes negative.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <vector>

#include "sampling/sparse_grid.hpp"
#include "sampling_test_support.hpp"

using namespace peristep::sampling;
using namespace sampling_test;

namespace {

// A polynomial as a sum of c * prod_d x_d^e_d.
struct Monomial {
  double c;
  std::vector<int> e;
};

double evaluate(const std::vector<Monomial>& f, std::span<const double> x) {
  double sum = 0;
  for (const Monomial& m : f) {
    double t = m.c;
    for (std::size_t d = 0; d < x.size(); ++d) t *= std::pow(x[d], m.e[d]);
    sum += t;
  }
  return sum;
}

// E[f] and Var[f] = E[f^2] - E[f]^2 from the exact moments of the laws (no quadrature).
std::pair<double, double> exactMeanVariance(const std::vector<Monomial>& f, std::span<const Law> laws) {
  double mean = 0, square = 0;
  for (const Monomial& a : f) {
    mean += a.c * exactMoment(laws, a.e);
    for (const Monomial& b : f) {
      std::vector<int> e(a.e.size());
      for (std::size_t d = 0; d < e.size(); ++d) e[d] = a.e[d] + b.e[d];
      square += a.c * b.c * exactMoment(laws, e);
    }
  }
  return {mean, square - mean * mean};
}

struct Estimates {
  double mean = 0, directVariance = 0, pceMean = 0, pceVariance = 0;
};

Estimates estimate(std::span<const Law> laws, int level, Family family, const std::function<double(std::span<const double>)>& f) {
  const SampleSet set = smolyakGrid(laws, level, family);
  const SparseProjection p = sparsePseudoSpectral(laws, level, family);
  std::vector<double> q(set.size());
  for (std::size_t k = 0; k < set.size(); ++k) q[k] = f(set.point(k));
  Estimates e;
  for (std::size_t k = 0; k < q.size(); ++k) e.mean += set.weights[k] * q[k];
  for (std::size_t k = 0; k < q.size(); ++k) e.directVariance += set.weights[k] * (q[k] - e.mean) * (q[k] - e.mean);
  std::vector<double> c(p.coefficients, 0.0);
  for (const SpectralTerm& t : p.terms) {
    REQUIRE(t.sample < q.size());
    c[t.coefficient] += t.factor * q[t.sample];
  }
  e.pceMean = c[0];
  for (std::size_t a = 1; a < c.size(); ++a) e.pceVariance += c[a] * c[a];
  return e;
}

}  // namespace

TEST_CASE("sparse_grid pce: the surrogate's variance is exact for polynomials of low degree in 2-3 variables",
          "[sampling][smolyak][pce]") {
  const std::vector<Law> three{Law::Normal, Law::Uniform, Law::Normal}, two{Law::Uniform, Law::Normal};
  // Total degree 3 with a mixed term: level 2 keeps p_a p_b with a + b <= 4 per pair of coordinates.
  const std::vector<Monomial> f3{{2, {0, 0, 0}}, {1, {1, 0, 0}}, {3, {1, 1, 0}}, {-1, {0, 0, 2}}, {0.5, {0, 3, 0}},
                                 {0.25, {1, 0, 1}}};
  const std::vector<Monomial> f2{{1, {0, 0}}, {-2, {2, 0}}, {1.5, {1, 1}}, {0.3, {0, 3}}, {0.7, {2, 1}}};
  for (const Family family : {Family::Gauss, Family::Nested})
    for (const auto& [laws, f] : {std::pair{three, f3}, std::pair{two, f2}})
      for (const int level : {2, 3}) {
        const auto [mean, variance] = exactMeanVariance(f, laws);
        const Estimates e = estimate(laws, level, family, [&](std::span<const double> x) { return evaluate(f, x); });
        INFO("dims " << laws.size() << ", level " << level << ", nested " << (family == Family::Nested));
        CHECK(e.pceMean == Approx(mean).epsilon(1e-12).margin(1e-12));
        CHECK(e.mean == Approx(mean).epsilon(1e-12).margin(1e-12));
        CHECK(e.pceVariance == Approx(variance).epsilon(1e-11));
      }
}

TEST_CASE("sparse_grid pce: x1 x2 has no variance in the level-1 surrogate and its exact variance at level 2",
          "[sampling][smolyak][pce]") {
  // f = x1 x2 (N(0,1) each): Var = 1. Level 1 keeps no p_1 p_1 product, so the surrogate has no variance
  // from it, while level 2 has it exactly.
  const std::vector<Law> laws{Law::Normal, Law::Normal};
  const auto f = [](std::span<const double> x) { return x[0] * x[1]; };
  CHECK(estimate(laws, 1, Family::Gauss, f).pceVariance == Approx(0).margin(1e-14));
  CHECK(estimate(laws, 2, Family::Gauss, f).pceVariance == Approx(1).epsilon(1e-12));
}

TEST_CASE("sparse_grid pce: the variance is >= 0 where the direct estimate is negative (20 dimensions, level 1)",
          "[sampling][smolyak][pce]") {
  // A spike at the centre node, weight -17/3 at level 1 in 20 dimensions: the direct estimate is
  // sum w_k (q_k - mean)^2 = -(17/3)(20/3)^2 + (40/6)(17/3)^2 = -1020/27 < 0.
  const std::vector<Law> laws(20, Law::Normal);
  const auto spike = [](std::span<const double> x) {
    for (double v : x)
      if (v != 0) return 0.0;
    return 1.0;
  };
  for (const Family family : {Family::Gauss, Family::Nested}) {
    const Estimates e = estimate(laws, 1, family, spike);
    CHECK(e.directVariance == Approx(-1020.0 / 27).epsilon(1e-12));
    CHECK(e.pceVariance > 0);
    CHECK(e.pceMean == Approx(e.mean).epsilon(1e-12));
  }
}
