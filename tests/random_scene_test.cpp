// The random-field side of the scenes: laws of the coordinates, the KL plate (refusal of a non-positive
// modulus unless the lognormal transform is chosen) and the exact moments of Tests 1-3 (000 Sec. 4).
#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "scenes/scene_model.hpp"

using namespace peristep;
using Catch::Matchers::Contains;

namespace {

SceneParameters klPlate(double xi0, MaterialTransform t) {
  SceneParameters p;
  p.scene = SceneId::KlPlate;
  p.grid = GridSpec{17, 17, 1.0, 1.0, 3.0};
  p.fieldStd = 0.5;
  p.correlationLength = 0.3;
  p.transform = t;
  p.xi = {xi0, 0.0, 0.0, 0.0};
  return p;
}

}  // namespace

TEST_CASE("random coordinates: each scene declares its laws and leaves the rest of xi unused", "[random]") {
  SceneParameters p;
  p.xi.assign(3, 0.0);
  p.scene = SceneId::Smooth;
  CHECK(xiDistribution(p, 0) == XiDistribution::Normal);
  CHECK(xiDistribution(p, 1) == XiDistribution::Unused);
  p.scene = SceneId::InterfaceCrack;
  CHECK(xiDistribution(p, 0) == XiDistribution::Normal);
  CHECK(xiDistribution(p, 1) == XiDistribution::Uniform);
  CHECK(xiDistribution(p, 2) == XiDistribution::Unused);
  p.scene = SceneId::GlassCeramic;  // the microstructure of a seed: nothing random in xi
  CHECK(randomCoordinates(p) == 0);
  p.pcaRealizations = 100;          // the PCA field: every entry
  CHECK(randomCoordinates(p) == 3);
  p.scene = SceneId::KlPlate;
  CHECK(randomCoordinates(p) == 3);
}

TEST_CASE("KL plate: a tail coordinate that makes E non-positive is refused unless the field is lognormal",
          "[random]") {
  try {
    SceneModel refused(klPlate(-8.0, MaterialTransform::Affine));
    FAIL("an affine field with E <= 0 was accepted");
  } catch (const InvalidInput& e) {
    CHECK_THAT(e.what(), Contains("<= 0 at point (x, y)"));
    CHECK_THAT(e.what(), Contains("lognormal"));
  }
  SceneModel accepted(klPlate(-8.0, MaterialTransform::Positive));
  for (double E : accepted.youngsModulus()) CHECK(E > 0);
  accepted.advance(1.0);
  for (double u : accepted.uy()) CHECK(std::isfinite(u));
  CHECK(accepted.retainedVariance() > 0.0);
  CHECK(accepted.retainedVariance() <= 1.0);

  // A moderate coordinate is fine either way, and the affine field is 1 + g: its mean over the plate
  // stays near 1 and it varies (the modes are not constant).
  SceneModel moderate(klPlate(1.0, MaterialTransform::Affine));
  double lo = 1e300, hi = -1e300;
  for (double E : moderate.youngsModulus()) lo = std::min(lo, E), hi = std::max(hi, E);
  CHECK(lo > 0);
  CHECK(hi - lo > 0.05);
}

TEST_CASE("exact moments of Test 1 agree with an independent integration over xi", "[random]") {
  SceneParameters p;
  p.scene = SceneId::Smooth;
  p.grid = GridSpec{9, 9, 1.0, 1.0, 3.0};
  p.xi = {0.0};
  SceneModel m(p);
  m.advance(2.0);  // the moments follow the load factor
  REQUIRE(m.hasExactMoments());
  // u0 = (sin x sin y, -cos x cos y) / (2 + sin(5 * 0.1 z)), z ~ N(0, 1): Simpson's rule on [-12, 12].
  constexpr int n = 24000;
  const double a = -12.0, step = 24.0 / n;
  double e1 = 0, e2 = 0;
  for (int k = 0; k <= n; ++k) {
    const double z = a + k * step, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    const double density = std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI);
    const double g = 1.0 / (2.0 + std::sin(0.5 * z));
    e1 += w * density * g;
    e2 += w * density * g * g;
  }
  e1 *= step / 3;
  e2 *= step / 3;
  const double sd = std::sqrt(e2 - e1 * e1);
  const auto meanUx = m.exactMoment(0), stdUy = m.exactMoment(3);
  for (std::size_t i = 0; i < m.x().size(); ++i) {
    const double x = m.x()[i], y = m.y()[i];
    CHECK(meanUx[i] == Approx(2.0 * std::sin(x) * std::sin(y) * e1).margin(1e-12));
    CHECK(stdUy[i] == Approx(2.0 * std::abs(std::cos(x) * std::cos(y)) * sd).margin(1e-12));
  }
}

TEST_CASE("exact moments: none for the glass-ceramic plate", "[random]") {
  SceneParameters p;
  p.scene = SceneId::GlassCeramic;
  p.grid = GridSpec{26, 13, 800e-6, 384e-6, 3.0};  // h = 32 um
  p.xi = {0.0};
  SceneModel m(p);
  CHECK_FALSE(m.hasExactMoments());
  CHECK(m.exactMoment(0).empty());
}

TEST_CASE("glass-ceramic PCA field: scales from the PCA variances, mean field at xi = 0, modes shared", "[random]") {
  SceneParameters p;
  p.scene = SceneId::GlassCeramic;
  p.grid = GridSpec{26, 13, 800e-6, 384e-6, 3.0};  // h = 32 um
  p.crystalFraction = 0.4;
  p.pcaRealizations = 200;
  p.xi = {0.0, 0.0, 0.0};
  SceneModel mean(p);
  const std::vector<double> s = mean.xiScales();
  REQUIRE(s.size() == 3);
  CHECK(s[0] >= s[1]);
  CHECK(s[1] >= s[2]);
  CHECK(s[2] > 0);
  CHECK(mean.retainedVariance() > 0);
  CHECK(mean.retainedVariance() < 1);
  // At xi = 0 the field is the mean indicator: E strictly between the phases almost everywhere.
  std::size_t between = 0;
  for (double E : mean.youngsModulus()) between += E > 80e9 && E < 133e9;
  CHECK(between > mean.youngsModulus().size() / 2);

  p.xi = {2.0, -1.0, 0.5};
  SceneModel other(p);
  CHECK(other.xiScales() == s);  // the same modes (cached), another sample
  CHECK(other.youngsModulus() != mean.youngsModulus());
  other.advance(SceneInputs{1.0, 0.05e-6});
  for (double u : other.uy()) CHECK(std::isfinite(u));
}
