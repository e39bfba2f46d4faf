// Patch test (DESIGN 5.1): for a quadratic displacement and constant moduli the discrete operator is
// exact, so it reproduces the Navier operator -(lambda+mu) grad div u - mu lap u to round-off. This is
// the test that catches sign and scaling mistakes in 000:(3.1)-(3.2).
#include <catch2/catch.hpp>
#include <memory>

#include "models/elastic_scene.hpp"
#include "models/lps_discretization.hpp"
#include "models/lps_material.hpp"
#include "solvers/static_lps.hpp"

using namespace peristep;

namespace {

// u = (a1 x^2 + a2 xy + a3 y^2 + 0.3 x, b1 x^2 + b2 xy + b3 y^2 - 0.2 y), constant E and nu.
class QuadraticScene final : public ElasticScene {
 public:
  explicit QuadraticScene(double nu) : nu_(nu), l_(planeStrain(E_, nu)) {}
  double poissonRatio() const override { return nu_; }
  double youngsModulus(double, double) const override { return E_; }
  Vec2 displacement(double x, double y) const override {
    return {a1 * x * x + a2 * x * y + a3 * y * y + 0.3 * x, b1 * x * x + b2 * x * y + b3 * y * y - 0.2 * y};
  }
  double divergence(double x, double y) const { return 2 * a1 * x + a2 * y + 0.3 + b2 * x + 2 * b3 * y - 0.2; }
  Vec2 bodyForce(double, double) const override {
    const double gradDiv[2] = {2 * a1 + b2, a2 + 2 * b3};
    const double lap[2] = {2 * a1 + 2 * a3, 2 * b1 + 2 * b3};
    return {-(l_.lambda + l_.mu) * gradDiv[0] - l_.mu * lap[0], -(l_.lambda + l_.mu) * gradDiv[1] - l_.mu * lap[1]};
  }

 private:
  static constexpr double E_ = 3.0, a1 = 0.7, a2 = -0.4, a3 = 0.25, b1 = -0.3, b2 = 0.9, b3 = 0.5;
  double nu_;
  Lame l_;
};

GridSpec patchGrid(double jitter) {
  GridSpec g;
  g.nx = g.ny = 17;
  g.deltaOverH = 3.0;
  g.jitter = jitter;
  return g;
}

}  // namespace

TEST_CASE("patch test: the assembled operator is exact for quadratic displacements", "[lps][patch]") {
  const double nu = GENERATE(0.3, 0.495);
  const double jitter = GENERATE(0.0, 0.2);
  INFO("nu = " << nu << ", jitter = " << jitter << " h");
  const QuadraticScene scene(nu);
  const LpsDiscretization d = LpsDiscretization::build(patchGrid(jitter));
  const PointCloud& c = d.cloud;
  const Lame l = planeStrain(3.0, nu);
  const std::vector<double> lambda(c.size(), l.lambda), mu(c.size(), l.mu);
  const LpsSystem sys = assembleLps(c, d.neighbours, d.weights, lambda, mu, d.dofs);

  // Exact unknowns (u, theta = div u) and prescribed collar data g.
  std::vector<double> x(static_cast<std::size_t>(d.dofs.size)), g(2 * c.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    const Vec2 u = scene.displacement(c.x[p], c.y[p]);
    if (d.dofs.u[p] >= 0) {
      x[static_cast<std::size_t>(d.dofs.u[p])] = u[0];
      x[static_cast<std::size_t>(d.dofs.u[p]) + 1] = u[1];
    } else {
      g[2 * p] = u[0];
      g[2 * p + 1] = u[1];
    }
    if (d.dofs.theta[p] >= 0) x[static_cast<std::size_t>(d.dofs.theta[p])] = scene.divergence(c.x[p], c.y[p]);
  }
  std::vector<double> Ax(x.size()), Bg(x.size());
  sys.A.multiply(x, Ax);
  sys.B.multiply(g, Bg);

  const Vec2 f = scene.bodyForce(0, 0);
  const double fScale = std::hypot(f[0], f[1]);
  double worstMomentum = 0.0, worstDilatation = 0.0;
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (d.dofs.u[p] >= 0)
      for (int a = 0; a < 2; ++a) {
        const auto r = static_cast<std::size_t>(d.dofs.u[p] + a);
        worstMomentum = std::max(worstMomentum, std::abs(Ax[r] + Bg[r] - f[static_cast<std::size_t>(a)]) / fScale);
      }
    if (d.dofs.theta[p] >= 0) {
      const auto r = static_cast<std::size_t>(d.dofs.theta[p]);
      worstDilatation = std::max(worstDilatation, std::abs(Ax[r] + Bg[r]));  // theta = O(1) here
    }
  }
  CHECK(worstMomentum < 1e-9);
  CHECK(worstDilatation < 1e-9);
}

TEST_CASE("patch test: the solver returns the quadratic displacement", "[lps][patch]") {
  const QuadraticScene scene(0.3);
  auto d = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(patchGrid(0.0)));
  StaticLps lps(d, scene);
  lps.solve();
  CHECK(lps.errorL2() < 1e-11);
}
