// One-dimensional rules (Gauss, nested), tensor grids and Monte Carlo of host/sampling: exactness
// against the laws' exact moments, the degree where exactness ends, and reproducibility.
#include <catch2/catch.hpp>

#include <array>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>

#include "sampling/gauss_rules.hpp"
#include "sampling/monte_carlo.hpp"
#include "sampling/nested_rules.hpp"
#include "sampling/tensor_grid.hpp"
#include "sampling_test_support.hpp"

using namespace peristep::sampling;
using namespace sampling_test;

namespace {

double sum(const std::vector<double>& v) {
  double s = 0;
  for (const double x : v) s += x;
  return s;
}

// E[pi_n^2] for the monic orthogonal polynomial pi_n: the error E[x^{2n}] - Q_n[x^{2n}] of the
// n-point Gauss rule (x^{2n} - pi_n^2 has degree < 2n, and Q_n[pi_n^2] = 0).
// Hermite: n!; Legendre with weight 1/2: 4^n (n!)^4 / ((2n)!^2 (2n+1)).
double gaussDeficiency(Law law, int n) {
  if (law == Law::Normal) return std::tgamma(n + 1.0);
  double r = 1;  // 2^n (n!)^2 / (2n)!, built as a product to stay in range
  for (int j = 1; j <= n; ++j) r *= 2.0 * j / (n + j);
  return r * r / (2 * n + 1);
}

// Legendre P_k (|P_k| <= 1 on [-1, 1]) or the normalized Hermite He_k / sqrt(k!) (E = 1): zero mean
// for k >= 1.
double classicalPolynomial(Law law, int k, double x) {
  double p = 1, pPrev = 0;
  for (int j = 0; j < k; ++j) {
    const double next = law == Law::Uniform ? ((2 * j + 1) * x * p - j * pPrev) / (j + 1)
                                            : (x * p - std::sqrt(static_cast<double>(j)) * pPrev) / std::sqrt(j + 1.0);
    pPrev = p;
    p = next;
  }
  return p;
}

void checkSymmetric(const Rule1D& rule) {
  const std::size_t n = rule.nodes.size();
  for (std::size_t i = 0; i < n; ++i) {
    CHECK(rule.nodes[i] == -rule.nodes[n - 1 - i]);
    CHECK(rule.weights[i] == rule.weights[n - 1 - i]);
    if (i > 0) CHECK(rule.nodes[i] > rule.nodes[i - 1]);
  }
  if (n % 2 == 1) CHECK(rule.nodes[n / 2] == 0.0);
}

}  // namespace

TEST_CASE("gauss rules integrate x^k exactly for k <= 2n-1 and not for k = 2n", "[sampling][gauss]") {
  for (const Law law : {Law::Normal, Law::Uniform}) {
    for (int n = 1; n <= 20; ++n) {
      INFO("law " << (law == Law::Normal ? "normal" : "uniform") << ", n = " << n);
      const Rule1D rule = gaussRule(law, n);
      REQUIRE(rule.nodes.size() == static_cast<std::size_t>(n));
      CHECK(sum(rule.weights) == Approx(1).epsilon(1e-14));
      checkSymmetric(rule);
      for (int k = 0; k <= 2 * n - 1; ++k) {
        INFO("k = " << k);
        CHECK(relativeError(integrate(rule, k), exactMoment(law, k)) < 1e-12);
      }
      // The miss at k = 2n is the exact amount theory predicts, and well above the tolerance above.
      const double exact = exactMoment(law, 2 * n), miss = exact - integrate(rule, 2 * n).value;
      CHECK(miss == Approx(gaussDeficiency(law, n)).epsilon(1e-2));
      CHECK(miss / exact > 1e-11);
    }
  }
}

TEST_CASE("gauss rules: known small rules", "[sampling][gauss]") {
  const Rule1D h3 = gaussRule(Law::Normal, 3);
  CHECK(h3.nodes[2] == Approx(std::sqrt(3.0)).epsilon(1e-15));
  CHECK(h3.weights[1] == Approx(2.0 / 3).epsilon(1e-15));
  CHECK(h3.weights[0] == Approx(1.0 / 6).epsilon(1e-15));
  const Rule1D l2 = gaussRule(Law::Uniform, 2);
  CHECK(l2.nodes[1] == Approx(1 / std::sqrt(3.0)).epsilon(1e-15));
  CHECK(l2.weights[0] == Approx(0.5).epsilon(1e-15));
  const Rule1D l5 = gaussRule(Law::Uniform, 5);  // Abramowitz-Stegun 25.4.29
  CHECK(l5.nodes[3] == Approx(0.538469310105683091).epsilon(1e-15));
  CHECK(l5.nodes[4] == Approx(0.906179845938663993).epsilon(1e-15));
  CHECK(l5.weights[2] == Approx(0.568888888888888889 / 2).epsilon(1e-15));
  CHECK_THROWS_AS(gaussRule(Law::Normal, 0), std::invalid_argument);
}

TEST_CASE("gauss rules stay accurate to 1e-14 up to 40 points", "[sampling][gauss]") {
  // Nodes: the Newton correction of the classical polynomial at each node; weights: the classical
  // closed forms, all evaluated here in long double by the textbook recurrences.
  for (const int n : {25, 32, 40}) {
    {
      INFO("Gauss-Hermite, n = " << n);
      const Rule1D rule = gaussRule(Law::Normal, n);
      long double factorial = 1;  // (n-1)!
      for (int j = 2; j < n; ++j) factorial *= j;
      for (int i = 0; i < n; ++i) {
        const long double x = rule.nodes[i];
        long double he = 1, hePrev = 0;  // He_k(x), He_{k-1}(x)
        for (int k = 0; k < n; ++k) {
          const long double next = x * he - k * hePrev;
          hePrev = he;
          he = next;
        }
        const long double correction = he / (n * hePrev);  // He_n' = n He_{n-1}
        CHECK(std::abs(static_cast<double>(correction)) < 1e-14 * std::max(1.0, std::abs(rule.nodes[i])));
        const long double w = factorial / (n * hePrev * hePrev);
        CHECK(rule.weights[i] == Approx(static_cast<double>(w)).epsilon(1e-13));
      }
    }
    {
      INFO("Gauss-Legendre, n = " << n);
      const Rule1D rule = gaussRule(Law::Uniform, n);
      for (int i = 0; i < n; ++i) {
        const long double x = rule.nodes[i];
        long double p = 1, pPrev = 0;
        for (int k = 0; k < n; ++k) {
          const long double next = ((2 * k + 1) * x * p - k * pPrev) / (k + 1);
          pPrev = p;
          p = next;
        }
        const long double derivative = n * (x * p - pPrev) / (x * x - 1);
        CHECK(std::abs(static_cast<double>(p / derivative)) < 1e-14);
        const long double w = 1 / ((1 - x * x) * derivative * derivative);  // weight 1/2 included
        CHECK(rule.weights[i] == Approx(static_cast<double>(w)).epsilon(1e-13));
      }
    }
  }
}

TEST_CASE("nested rules: sizes, nestedness, exactness degree", "[sampling][nested]") {
  const std::array<std::vector<std::size_t>, 2> sizes{std::vector<std::size_t>{1, 3, 9, 19, 35},
                                                       std::vector<std::size_t>{1, 3, 7, 15, 31}};
  for (const Law law : {Law::Normal, Law::Uniform}) {
    const auto& expectedSizes = sizes[law == Law::Normal ? 0 : 1];
    REQUIRE(nestedMaxLevel(law) == static_cast<int>(expectedSizes.size()) - 1);
    for (int level = 0; level <= nestedMaxLevel(law); ++level) {
      INFO("law " << (law == Law::Normal ? "normal" : "uniform") << ", level " << level);
      const Rule1D rule = nestedRule(law, level);
      REQUIRE(rule.nodes.size() == expectedSizes[level]);
      CHECK(sum(rule.weights) == Approx(1).epsilon(1e-14));
      checkSymmetric(rule);
      if (level > 0) {
        // Every node of the previous level, as the very same double.
        const Rule1D previous = nestedRule(law, level - 1);
        const std::set<double> nodes(rule.nodes.begin(), rule.nodes.end());
        for (const double x : previous.nodes) CHECK(nodes.count(x) == 1);
      }
      const int degree = nestedRuleDegree(law, level);
      for (int k = 0; k <= degree; ++k) {
        INFO("k = " << k);
        CHECK(relativeError(integrate(rule, k), exactMoment(law, k)) < 1e-12);
      }
      // Beyond the degree: x^{degree+1} itself may miss by less than rounding (by 1e-15 for 31
      // Patterson points), so use the orthogonal polynomial of that degree, whose mean is 0.
      // It misses by 1e-8 (35 Genz-Keister points) to 0.7, far above the rounding scale.
      double beyond = 0, scale = 1;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        const double term = rule.weights[i] * classicalPolynomial(law, degree + 1, rule.nodes[i]);
        beyond += term;
        scale += std::abs(term);
      }
      INFO("mean of the degree-" << degree + 1 << " polynomial: " << beyond << ", scale " << scale);
      CHECK(std::abs(beyond) > 1e-11 * scale);
    }
    CHECK_THROWS_AS(nestedRule(law, nestedMaxLevel(law) + 1), std::invalid_argument);
    CHECK_THROWS_AS(nestedRule(law, -1), std::invalid_argument);
  }
  CHECK(nestedRuleDegree(Law::Normal, 4) == 51);
  CHECK(nestedRuleDegree(Law::Uniform, 4) == 47);
}

TEST_CASE("nested rules match published Gauss-Patterson and Genz-Keister nodes", "[sampling][nested]") {
  // Level 1 is the 3-point Gauss rule of each law.
  for (const Law law : {Law::Normal, Law::Uniform}) {
    const Rule1D nested = nestedRule(law, 1), gauss = gaussRule(law, 3);
    for (int i = 0; i < 3; ++i) {
      CHECK(nested.nodes[i] == Approx(gauss.nodes[i]).epsilon(1e-15));
      CHECK(nested.weights[i] == Approx(gauss.weights[i]).epsilon(1e-14));
    }
  }
  // Patterson (1968), 7 points; Genz-Keister (1996), 9 points scaled by sqrt(2) to the N(0,1) weight.
  const Rule1D p7 = nestedRule(Law::Uniform, 2);
  CHECK(p7.nodes[4] == Approx(0.434243749346802558).epsilon(1e-14));
  CHECK(p7.nodes[6] == Approx(0.960491268708020283).epsilon(1e-14));
  const Rule1D k9 = nestedRule(Law::Normal, 2);
  CHECK(k9.nodes[5] == Approx(0.741095349994540853).epsilon(1e-13));
  CHECK(k9.nodes[7] == Approx(2.861279576057058183).epsilon(1e-13));
  CHECK(k9.nodes[8] == Approx(4.184956017672732047).epsilon(1e-13));
  // The 19-node Genz-Keister rule is known to carry negative weights.
  const Rule1D k19 = nestedRule(Law::Normal, 3);
  CHECK(*std::min_element(k19.weights.begin(), k19.weights.end()) < 0);
}

TEST_CASE("tensor grid: n^N points, exact for per-dimension degree <= 2n-1", "[sampling][tensor]") {
  const std::vector<Law> laws{Law::Normal, Law::Uniform, Law::Normal};
  for (std::size_t dims = 1; dims <= 3; ++dims) {
    const std::span<const Law> first(laws.data(), dims);
    for (int n = 1; n <= 4; ++n) {
      INFO("N = " << dims << ", n = " << n);
      const SampleSet grid = tensorGrid(first, n);
      REQUIRE(grid.dims == dims);
      REQUIRE(grid.size() == static_cast<std::size_t>(std::pow(n, dims)));
      REQUIRE(grid.points.size() == grid.size() * dims);
      CHECK(sum(grid.weights) == Approx(1).epsilon(1e-14));
      // All exponent vectors with every entry <= 2n-1 (total degree up to N(2n-1)).
      std::vector<int> e(dims, 0);
      for (;;) {
        INFO("exponents " << Catch::Detail::stringify(e));
        CHECK(relativeError(integrate(grid, e), exactMoment(first, e)) < 1e-12);
        std::size_t d = 0;
        while (d < dims && ++e[d] > 2 * n - 1) e[d++] = 0;
        if (d == dims) break;
      }
      // Degree 2n in one coordinate is beyond the rule.
      for (std::size_t d = 0; d < dims; ++d) {
        std::vector<int> beyond(dims, 0);
        beyond[d] = 2 * n;
        CHECK(relativeError(integrate(grid, beyond), exactMoment(first, beyond)) > 1e-11);
      }
    }
  }
  // The last coordinate varies fastest.
  const SampleSet grid = tensorGrid(std::span<const Law>(laws.data(), 2), 2);
  const Rule1D h2 = gaussRule(Law::Normal, 2), l2 = gaussRule(Law::Uniform, 2);
  CHECK(grid.point(1)[0] == h2.nodes[0]);
  CHECK(grid.point(1)[1] == l2.nodes[1]);
  CHECK(grid.point(2)[0] == h2.nodes[1]);
  CHECK_THROWS_AS(tensorGrid(laws, 0), std::invalid_argument);
  CHECK_THROWS_AS(tensorGrid(std::vector<Law>(64, Law::Normal), 2), std::length_error);
}

TEST_CASE("monte carlo: reproducible, seed-dependent, extendable", "[sampling][montecarlo]") {
  const std::vector<Law> laws{Law::Normal, Law::Uniform, Law::Normal};
  const SampleSet a = monteCarlo(laws, 100, 42), b = monteCarlo(laws, 100, 42), c = monteCarlo(laws, 100, 43);
  CHECK(a.points == b.points);
  CHECK(a.points != c.points);
  CHECK(a.dims == 3);
  REQUIRE(a.size() == 100);
  for (const double w : a.weights) CHECK(w == 0.01);
  // The first 40 points of a 100-point set are the 40-point set.
  const SampleSet prefix = monteCarlo(laws, 40, 42);
  CHECK(std::equal(prefix.points.begin(), prefix.points.end(), a.points.begin()));

  // The documented transform, replayed on the standard engine.
  std::mt19937_64 engine(42);
  const auto unit = [&] { return static_cast<double>(engine() >> 11) * 0x1.0p-53; };
  const double u1 = unit(), u2 = unit(), u3 = unit();
  const double radius = std::sqrt(-2 * std::log(1 - u1)), angle = 2 * std::numbers::pi * u2;
  CHECK(a.point(0)[0] == Approx(radius * std::cos(angle)).epsilon(1e-15));
  CHECK(a.point(0)[1] == Approx(2 * u3 - 1).epsilon(1e-15));
  CHECK(a.point(0)[2] == Approx(radius * std::sin(angle)).epsilon(1e-15));
}

TEST_CASE("monte carlo: sample moments within 5 sigma", "[sampling][montecarlo]") {
  const std::vector<Law> laws{Law::Normal, Law::Uniform, Law::Normal, Law::Uniform, Law::Normal};
  const std::size_t count = 20000;
  const SampleSet set = monteCarlo(laws, count, 2024);
  const double q = static_cast<double>(count);
  for (std::size_t d = 0; d < laws.size(); ++d) {
    INFO("coordinate " << d);
    double m1 = 0, m2 = 0, m4 = 0, lo = 0, hi = 0;
    for (std::size_t k = 0; k < count; ++k) {
      const double x = set.point(k)[d];
      m1 += x / q;
      m2 += x * x / q;
      m4 += x * x * x * x / q;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    const bool normal = laws[d] == Law::Normal;
    // Standard deviations of the sample moments from E[x^2], E[x^4], E[x^8] of each law.
    const double ex2 = normal ? 1 : 1.0 / 3, ex4 = normal ? 3 : 1.0 / 5, ex8 = normal ? 105 : 1.0 / 9;
    CHECK(std::abs(m1) < 5 * std::sqrt(ex2 / q));
    CHECK(std::abs(m2 - ex2) < 5 * std::sqrt((ex4 - ex2 * ex2) / q));
    CHECK(std::abs(m4 - ex4) < 5 * std::sqrt((ex8 - ex4 * ex4) / q));
    if (normal) {
      CHECK(hi > 3);  // 20000 normal draws reach beyond 3 sigma on both sides
      CHECK(lo < -3);
    } else {
      CHECK(lo >= -1);
      CHECK(hi < 1);
    }
  }
}
