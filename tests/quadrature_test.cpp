#include <catch2/catch.hpp>
#include <cmath>

#include "models/lps_discretization.hpp"
#include "quadrature/optimization_weights.hpp"

using namespace peristep;

TEST_CASE("exact moments match a numerical polar integral", "[quadrature]") {
  // int_{B_delta} z1^a z2^b/|z|^3 = int_0^delta r^(a+b-2) dr * int cos^a sin^b dt, by the midpoint rule.
  const double delta = 0.7;
  for (const Monomial& m : momentMonomials()) {
    const int n = 20000;
    double angular = 0.0;
    for (int k = 0; k < n; ++k) {
      const double t = 2.0 * M_PI * (k + 0.5) / n;
      angular += std::pow(std::cos(t), m.a) * std::pow(std::sin(t), m.b) * 2.0 * M_PI / n;
    }
    const double radial = std::pow(delta, m.a + m.b - 1) / (m.a + m.b - 1);
    CHECK(exactMoment(m, delta) == Approx(radial * angular).margin(1e-12));
  }
  CHECK(momentMonomials().size() == 18);
}

TEST_CASE("optimization weights reproduce all 18 constraint integrals", "[quadrature]") {
  GridSpec g;
  g.nx = g.ny = 33;
  const double jitter = GENERATE(0.0, 0.2);
  const double deltaOverH = GENERATE(3.0, 4.0);
  g.jitter = jitter;
  g.deltaOverH = deltaOverH;
  const LpsDiscretization d = LpsDiscretization::build(g);
  const auto active = d.dofs.thetaPoints();
  double worst = 0.0;
  std::size_t checked = 0;
  for (std::size_t p = 0; p < d.cloud.size(); ++p) {
    if (!active[p]) continue;
    worst = std::max(worst, constraintError(d.cloud, d.neighbours, d.weights, p));
    ++checked;
  }
  INFO("jitter " << jitter << ", delta/h " << deltaOverH << ", " << checked << " points");
  CHECK(checked > d.cloud.domain.size());
  CHECK(worst < 1e-12);
}

TEST_CASE("weights are computed only where a dilatation is needed", "[quadrature]") {
  GridSpec g;
  g.nx = g.ny = 9;
  const LpsDiscretization d = LpsDiscretization::build(g);
  const auto active = d.dofs.thetaPoints();
  for (std::size_t p = 0; p < d.cloud.size(); ++p)
    for (std::size_t k = d.neighbours.begin(p); k < d.neighbours.end(p); ++k)
      if (!active[p]) REQUIRE(d.weights[k] == 0.0);
}
