// Karhunen-Loeve fields (random/kl_field.hpp): dense against randomized eigenpairs, the separable
// Gaussian kernel, the exponential kernel's analytic 1D spectrum, and the tail behaviour of the
// affine and positive material transforms.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <vector>

#include "core/errors.hpp"
#include "random/kl_field.hpp"

using namespace peristep;
using Catch::Matchers::Contains;

namespace {

// Cell centres of an nx x ny grid of spacing h starting at the origin.
struct Grid {
  std::vector<double> x, y;
  double h;
  Grid(std::size_t nx, std::size_t ny, double spacing) : h(spacing) {
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        x.push_back((static_cast<double>(i) + 0.5) * h);
        y.push_back((static_cast<double>(j) + 0.5) * h);
      }
  }
};

// Eigenvalues (descending) of h C_1D on n cell centres of spacing h for the 1D Gaussian kernel.
Eigen::VectorXd gaussian1D(std::size_t n, double h, double l) {
  Eigen::MatrixXd A(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double d = (static_cast<double>(i) - static_cast<double>(j)) * h;
      A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = h * std::exp(-d * d / (l * l));
    }
  Eigen::VectorXd v = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues();
  return v.reverse();
}

// Root of f on [a, b] where f changes sign, by bisection.
double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// Continuous eigenvalues of s^2 exp(-|x - y|/l) on [-a, a] (Ghanem and Spanos 1991, Sec. 2.3.3):
// lambda = 2 c s^2 / (w^2 + c^2), c = 1/l, with c - w tan(w a) = 0 (even modes) or w + c tan(w a) = 0
// (odd modes); the n-th root of each lies in ((n - 1/2) pi/a, ...) intervals between the poles of tan.
std::vector<double> exponentialSpectrum1D(double a, double l, double s, std::size_t count) {
  const double c = 1.0 / l, pi = std::acos(-1.0), eps = 1e-12;
  std::vector<double> w;
  for (int n = 0; static_cast<std::size_t>(w.size()) < 2 * count; ++n) {
    // even: in (n pi/a, (n + 1/2) pi/a); odd: in ((n + 1/2) pi/a, (n + 1) pi/a)
    w.push_back(bisect([&](double t) { return c - t * std::tan(t * a); }, n * pi / a + eps, (n + 0.5) * pi / a - eps));
    w.push_back(bisect([&](double t) { return t + c * std::tan(t * a); }, (n + 0.5) * pi / a + eps, (n + 1) * pi / a - eps));
  }
  std::vector<double> lambda;
  for (double t : w) lambda.push_back(2.0 * c * s * s / (t * t + c * c));
  std::sort(lambda.rbegin(), lambda.rend());
  lambda.resize(count);
  return lambda;
}

}  // namespace

TEST_CASE("KL: dense and randomized eigenpairs agree on a medium grid", "[random][kl]") {
  const Grid g(32, 28, 1.0 / 32.0);  // 896 points
  for (const CovarianceKind kind : {CovarianceKind::Exponential, CovarianceKind::Gaussian}) {
    KlSpec spec;
    spec.kind = kind;
    spec.correlationLength = 0.3;
    spec.standardDeviation = 0.5;
    spec.modes = 10;
    spec.solver = KlSolver::Dense;
    const KlField dense(g.x, g.y, g.h, spec);
    spec.solver = KlSolver::Randomized;
    spec.oversampling = 20;
    spec.powerIterations = 6;
    const KlField randomized(g.x, g.y, g.h, spec);
    REQUIRE(dense.usedDenseSolver());
    REQUIRE_FALSE(randomized.usedDenseSolver());
    const double rel = ((dense.eigenvalues() - randomized.eigenvalues()).array() / dense.eigenvalues().array())
                           .abs()
                           .maxCoeff();
    INFO("kernel " << (kind == CovarianceKind::Exponential ? "exponential" : "gaussian") << ": max relative eigenvalue difference "
                   << rel << ", retained variance " << dense.retainedVarianceFraction());
    CHECK(rel < 1e-8);
    CHECK(randomized.retainedVarianceFraction() == Approx(dense.retainedVarianceFraction()).epsilon(1e-8));
    // The leading mode is simple: the functions agree pointwise (signs are fixed by convention).
    CHECK((dense.eigenfunctions().col(0) - randomized.eigenfunctions().col(0)).cwiseAbs().maxCoeff() <
          1e-6 * dense.eigenfunctions().col(0).cwiseAbs().maxCoeff());
    // Normalization: int phi_k phi_m dx = delta_km on the cells.
    const Eigen::MatrixXd gram = g.h * g.h * randomized.eigenfunctions().transpose() * randomized.eigenfunctions();
    CHECK((gram - Eigen::MatrixXd::Identity(10, 10)).cwiseAbs().maxCoeff() < 1e-12);
    WARN("KL " << (kind == CovarianceKind::Exponential ? "exponential" : "gaussian")
               << " kernel, l = 0.3, 10 modes on 896 points: retained variance " << dense.retainedVarianceFraction());
  }
}

TEST_CASE("KL: the separable Gaussian kernel has the products of the 1D eigenvalues", "[random][kl]") {
  // exp(-(dx^2 + dy^2)/l^2) = exp(-dx^2/l^2) exp(-dy^2/l^2): h^2 C = (h C_x) (x) (h C_y) on a tensor grid.
  const std::size_t nx = 40, ny = 24;
  const double h = 0.025, l = 0.2, s = 1.3;
  const Grid g(nx, ny, h);
  KlSpec spec;
  spec.kind = CovarianceKind::Gaussian;
  spec.correlationLength = l;
  spec.standardDeviation = s;
  spec.modes = 12;
  const KlField field(g.x, g.y, h, spec);
  REQUIRE(field.usedDenseSolver());  // 960 points: below the dense limit

  const Eigen::VectorXd ex = gaussian1D(nx, h, l), ey = gaussian1D(ny, h, l);
  std::vector<double> products;
  for (Eigen::Index i = 0; i < ex.size(); ++i)
    for (Eigen::Index j = 0; j < ey.size(); ++j) products.push_back(s * s * ex[i] * ey[j]);
  std::sort(products.rbegin(), products.rend());
  for (std::size_t k = 0; k < spec.modes; ++k)
    CHECK(field.eigenvalues()[static_cast<Eigen::Index>(k)] == Approx(products[k]).epsilon(1e-11));

  // Randomized path on the same grid (12 modes, 15 extra vectors, 5 subspace iterations).
  spec.solver = KlSolver::Randomized;
  spec.oversampling = 15;
  spec.powerIterations = 5;
  const KlField fast(g.x, g.y, h, spec);
  for (std::size_t k = 0; k < spec.modes; ++k)
    CHECK(fast.eigenvalues()[static_cast<Eigen::Index>(k)] == Approx(products[k]).epsilon(1e-9));
}

TEST_CASE("KL: exponential kernel on a row of points matches the analytic 1D spectrum", "[random][kl]") {
  // One row of N cells of width h on [-a, a]: h^2 C = h (h C_1D), so lambda / h -> continuous eigenvalues.
  const std::size_t n = 1000;
  const double a = 0.5, h = 2 * a / static_cast<double>(n), l = 0.4, s = 0.8;
  std::vector<double> x(n), y(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) x[i] = -a + (static_cast<double>(i) + 0.5) * h;
  KlSpec spec;
  spec.kind = CovarianceKind::Exponential;
  spec.correlationLength = l;
  spec.standardDeviation = s;
  spec.modes = 6;
  const KlField field(x, y, h, spec);
  const std::vector<double> exact = exponentialSpectrum1D(a, l, s, spec.modes);
  for (std::size_t k = 0; k < spec.modes; ++k) {
    const double discrete = field.eigenvalues()[static_cast<Eigen::Index>(k)] / h;
    INFO("mode " << k << ": discrete " << discrete << ", analytic " << exact[k]);
    // Midpoint-rule error ~ (w h)^2 / 24 relative: 1e-5 for the sixth mode (w ~ 5 pi) at h = 1e-3.
    CHECK(discrete == Approx(exact[k]).epsilon(5e-5));
  }
}

TEST_CASE("KL: retained variance fraction grows with the modes and is 1 with all of them", "[random][kl]") {
  const Grid g(12, 10, 0.1);
  KlSpec spec;
  spec.correlationLength = 0.25;
  spec.standardDeviation = 2.0;
  double previous = 0;
  for (std::size_t k : {1, 5, 20, 60}) {
    spec.modes = k;
    const KlField f(g.x, g.y, g.h, spec);
    INFO(k << " modes: retained " << f.retainedVarianceFraction());
    CHECK(f.retainedVarianceFraction() > previous);
    CHECK(f.retainedVarianceFraction() < 1.0);
    previous = f.retainedVarianceFraction();
  }
  spec.modes = g.x.size();
  const KlField all(g.x, g.y, g.h, spec);
  CHECK(all.retainedVarianceFraction() == Approx(1.0).epsilon(1e-12));
  // With every mode the pointwise variance of g is s^2: the positive transform then uses s^2 itself.
  std::vector<double> zero(all.modes(), 0.0);
  const std::vector<double> E = all.materialField(3.0, zero, MaterialTransform::Positive);
  CHECK(E[17] == Approx(3.0 * std::exp(-0.5 * 4.0)).epsilon(1e-10));
}

TEST_CASE("KL: a tail coordinate makes the affine field non-positive and the positive transform accepts it",
          "[random][kl]") {
  const Grid g(20, 20, 0.05);
  KlSpec spec;
  spec.kind = CovarianceKind::Exponential;
  spec.correlationLength = 0.3;
  spec.standardDeviation = 0.5;
  spec.modes = 5;
  const KlField field(g.x, g.y, g.h, spec);
  const std::vector<double> xi{-8.0, 0.0, 0.0, 0.0, 0.0};
  const double E0 = 70e9;

  // The message names the point of the smallest value, with that value, and the remedy.
  const std::vector<double> gField = field.sample(xi);
  const auto worst = static_cast<std::size_t>(std::min_element(gField.begin(), gField.end()) - gField.begin());
  std::ostringstream point, value;
  point << "(x, y) = (" << g.x[worst] << ", " << g.y[worst] << ")";
  value << E0 * (1.0 + gField[worst]);
  REQUIRE(E0 * (1.0 + gField[worst]) <= 0);
  CHECK_THROWS_AS(field.materialField(E0, xi, MaterialTransform::Affine), InvalidInput);
  CHECK_THROWS_WITH(field.materialField(E0, xi, MaterialTransform::Affine),
                    Contains(point.str()) && Contains(value.str()) && Contains("<= 0") &&
                        Contains("choose the positive (lognormal) transform"));
  CHECK_THROWS_WITH(field.materialField(E0, xi, MaterialTransform::Affine, "G"), Contains("G = G0 (1 + g)"));

  const std::vector<double> E = field.materialField(E0, xi, MaterialTransform::Positive);
  REQUIRE(E.size() == g.x.size());
  CHECK(std::all_of(E.begin(), E.end(), [](double e) { return std::isfinite(e) && e > 0; }));
  // The same xi scaled into the bulk is accepted by the affine field, and it is linear in xi.
  const std::vector<double> mild{-0.5, 0.0, 0.0, 0.0, 0.0};
  const std::vector<double> affine = field.materialField(E0, mild, MaterialTransform::Affine);
  CHECK(affine[worst] == Approx(E0 * (1.0 + gField[worst] / 16.0)).epsilon(1e-12));
}

TEST_CASE("KL: the positive transform has mean E0 at every point", "[random][kl]") {
  // Monte Carlo over xi: E[exp(g - v/2)] = 1 when v is the variance of the truncated g.
  const Grid g(8, 8, 0.125);
  KlSpec spec;
  spec.correlationLength = 0.5;
  spec.standardDeviation = 0.4;
  spec.modes = 4;
  const KlField field(g.x, g.y, g.h, spec);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  const int samples = 40000;
  std::vector<double> mean(g.x.size(), 0.0);
  std::vector<double> xi(4);
  for (int s = 0; s < samples; ++s) {
    for (double& v : xi) v = normal(rng);
    const std::vector<double> E = field.materialField(1.0, xi, MaterialTransform::Positive);
    for (std::size_t i = 0; i < E.size(); ++i) mean[i] += E[i] / samples;
  }
  // std of exp(g - v/2) is sqrt(exp(v) - 1) < 0.42 here: 4 standard errors ~ 0.0084.
  for (std::size_t i : {0, 27, 63}) CHECK(mean[i] == Approx(1.0).margin(0.0084));
}

TEST_CASE("KL: invalid input is rejected with InvalidInput", "[random][kl]") {
  const Grid g(5, 5, 0.2);
  KlSpec spec;
  spec.modes = 3;
  CHECK_NOTHROW(KlField(g.x, g.y, g.h, spec));
  KlSpec bad = spec;
  bad.correlationLength = -1;
  CHECK_THROWS_AS(KlField(g.x, g.y, g.h, bad), InvalidInput);
  bad = spec;
  bad.standardDeviation = 0;
  CHECK_THROWS_AS(KlField(g.x, g.y, g.h, bad), InvalidInput);
  bad = spec;
  bad.modes = 26;
  CHECK_THROWS_AS(KlField(g.x, g.y, g.h, bad), InvalidInput);
  CHECK_THROWS_AS(KlField(g.x, g.y, 0.0, spec), InvalidInput);
  CHECK_THROWS_AS(KlField(std::span<const double>(g.x).first(3), g.y, g.h, spec), InvalidInput);
  const KlField f(g.x, g.y, g.h, spec);
  CHECK_THROWS_AS(f.sample(std::vector<double>{1.0, 2.0}), InvalidInput);
  CHECK_THROWS_AS(f.sample(std::vector<double>{1.0, std::nan(""), 0.0}), InvalidInput);
  CHECK_THROWS_AS(f.materialField(-1.0, std::vector<double>{0.0, 0.0, 0.0}, MaterialTransform::Positive), InvalidInput);
}
