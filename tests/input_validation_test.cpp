// Non-physical or inconsistent input is refused with a precise message before any work is done.
#include <catch2/catch.hpp>
#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "fracture/bond_state.hpp"
#include "scenes/manufactured.hpp"
#include "scenes/scene_model.hpp"
#include "solvers/static_lps.hpp"

using namespace peristep;
using Catch::Matchers::Contains;

namespace {

SceneParameters valid() {
  SceneParameters p;
  p.grid.nx = p.grid.ny = 9;
  p.xi = {0.0};
  return p;
}

void requireRejected(const SceneParameters& p, const std::string& fragment) {
  REQUIRE_THROWS_AS(validate(p), InvalidInput);
  REQUIRE_THROWS_WITH(SceneModel(p), Contains(fragment));
}

// A scene whose modulus goes non-positive somewhere: rejected with the location.
class NegativeModulus final : public ElasticScene {
 public:
  double poissonRatio() const override { return 0.3; }
  double youngsModulus(double x, double) const override { return x > 0.25 ? -1.0 : 1.0; }
  Vec2 bodyForce(double, double) const override { return {0, 0}; }
  Vec2 displacement(double, double) const override { return {0, 0}; }
};

// A uniform material under its own weight.
class Weight final : public ElasticScene {
 public:
  double poissonRatio() const override { return 0.3; }
  double youngsModulus(double, double) const override { return 1.0; }
  Vec2 bodyForce(double, double) const override { return {0, -1}; }
  Vec2 displacement(double, double) const override { return {0, 0}; }
};

}  // namespace

TEST_CASE("valid parameters pass", "[validation]") { REQUIRE_NOTHROW(validate(valid())); }

TEST_CASE("non-physical and inconsistent parameters are rejected", "[validation]") {
  SceneParameters p = valid();
  SECTION("nu >= 0.5") {
    p.poissonRatio = 0.5;
    requireRejected(p, "Poisson ratio");
  }
  SECTION("nu <= -1") {
    p.poissonRatio = -1.0;
    requireRejected(p, "Poisson ratio");
  }
  SECTION("NaN nu") {
    p.poissonRatio = std::nan("");
    requireRejected(p, "Poisson ratio");
  }
  SECTION("delta < h") {
    p.grid.deltaOverH = 0.9;
    requireRejected(p, "horizon smaller than the grid spacing");
  }
  SECTION("empty domain: one point per side") {
    p.grid.nx = 1;
    requireRejected(p, "empty domain");
  }
  SECTION("empty domain: zero length") {
    p.grid.Lx = 0.0;
    requireRejected(p, "empty domain");
  }
  SECTION("non-uniform spacing") {
    p.grid.Ly = 2.0;
    requireRejected(p, "uniform");
  }
  SECTION("too few random coordinates") {
    p.scene = SceneId::Composite;
    requireRejected(p, "random coordinates");
  }
  SECTION("non-finite xi") {
    p.xi = {INFINITY};
    requireRejected(p, "xi[0]");
  }
  SECTION("non-positive modulus contrast") {
    p.modulusContrast = 0.0;
    requireRejected(p, "modulusContrast");
  }
}

TEST_CASE("a non-positive Young's modulus is rejected with its location", "[validation]") {
  GridSpec g;
  g.nx = g.ny = 9;
  auto d = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(g));
  const NegativeModulus scene;
  REQUIRE_THROWS_WITH(StaticLps(d, scene), Contains("Young's modulus must be positive") && Contains(" at ("));
}

TEST_CASE("a piece that pre-cracks cut loose is refused when a body force loads it", "[validation]") {
  GridSpec g;
  g.nx = g.ny = 17;
  auto d = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(g));
  const PointCloud& c = d->cloud;
  double lo = c.x[c.domain.front()], hi = lo;
  for (std::size_t p : c.domain) lo = std::min(lo, c.x[p]), hi = std::max(hi, c.x[p]);
  // A square whose sides and corners miss the lattice's points and bonds' lines (the domain is square).
  const double x0 = lo + 0.3 * (hi - lo) + 0.010, x1 = lo + 0.7 * (hi - lo) + 0.010;
  const double y0 = lo + 0.3 * (hi - lo) + 0.023, y1 = lo + 0.7 * (hi - lo) + 0.023;
  const std::vector<Segment> square{{x0, y0, x1, y0}, {x1, y0, x1, y1}, {x1, y1, x0, y1}, {x0, y1, x0, y0}};
  const Weight scene;
  REQUIRE_NOTHROW(StaticLps(d, scene));
  REQUIRE_THROWS_WITH(StaticLps(d, scene, LinearSolverKind::Umfpack, intactBonds(c, d->neighbours, square)),
                      Contains("no bond holds to the collar carries a body force") && Contains(" at ("));
}

TEST_CASE("a linear solver is chosen by its one name, an unknown name is refused", "[validation][solvers]") {
  CHECK(linearSolverKind("sparseLU") == LinearSolverKind::SparseLu);
  REQUIRE_THROWS_WITH(linearSolverKind("sparselu"),
                      "unknown linear solver 'sparselu' (known: umfpack, umfpackAmd, sparseLU, bicgstabIlut)");
}
