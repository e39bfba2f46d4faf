// A glass-ceramic seed is one material at every grid (scenes/microstructure.hpp): the crystals are
// placed in continuous coordinates and only then sampled onto the grid.
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/point_cloud.hpp"
#include "scenes/microstructure.hpp"

using namespace peristep;

namespace {

PointCloud plate(double h) {
  GridSpec g;
  g.Lx = 800e-6;
  g.Ly = 400e-6;
  g.nx = static_cast<std::size_t>(std::lround(g.Lx / h)) + 1;
  g.ny = static_cast<std::size_t>(std::lround(g.Ly / h)) + 1;
  return makeRectangle(g);
}

// Indicator of the h = 8 um points read at the same points of a finer plate (every `ratio`-th grid line).
std::size_t mismatches(const PointCloud& coarse, const std::vector<std::uint8_t>& Rc, const PointCloud& fine,
                       const std::vector<std::uint8_t>& Rf, std::size_t ratio) {
  const std::size_t gxc = coarse.nx + 2 * coarse.layers, gxf = fine.nx + 2 * fine.layers;
  std::size_t differ = 0;
  for (std::size_t p : coarse.domain) {
    const std::size_t i = p % gxc - coarse.layers, j = p / gxc - coarse.layers;
    const std::size_t q = (j * ratio + fine.layers) * gxf + i * ratio + fine.layers;
    REQUIRE(std::abs(fine.x[q] - coarse.x[p]) < 1e-12);
    REQUIRE(std::abs(fine.y[q] - coarse.y[p]) < 1e-12);
    differ += Rc[p] != Rf[q];
  }
  return differ;
}

}  // namespace

TEST_CASE("a microstructure seed is the same material at h = 8, 4 and 2 um", "[random][microstructure]") {
  const PointCloud h8 = plate(8e-6), h4 = plate(4e-6), h2 = plate(2e-6);
  for (const double f : {0.2, 0.8}) {
    for (const std::uint64_t seed : {1u, 7u}) {
      const auto R8 = generateMicrostructure(h8, f, seed), R4 = generateMicrostructure(h4, f, seed),
                 R2 = generateMicrostructure(h2, f, seed);
      INFO("f = " << f << ", seed " << seed);
      CHECK(mismatches(h8, R8, h4, R4, 2) == 0);
      CHECK(mismatches(h8, R8, h2, R2, 4) == 0);
      CHECK(mismatches(h4, R4, h2, R2, 2) == 0);
      // The fraction is reached on the placement raster; a grid sees it within its sampling error.
      CHECK(std::abs(crystalFraction(h2, R2) - f) < 0.01);
      CHECK(std::abs(crystalFraction(h8, R8) - f) < 0.03);
    }
  }
}

TEST_CASE("crystal placement depends on the seed and the fraction only", "[random][microstructure]") {
  const auto a = placeCrystals(800e-6, 400e-6, 0.4, 3), b = placeCrystals(800e-6, 400e-6, 0.4, 3);
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) CHECK((a[k].cx == b[k].cx && a[k].cy == b[k].cy && a[k].angle == b[k].angle));
  const auto c = placeCrystals(800e-6, 400e-6, 0.4, 4);
  CHECK(c.front().cx != a.front().cx);
  // A higher fraction continues the same sequence of crystals.
  const auto more = placeCrystals(800e-6, 400e-6, 0.6, 3);
  REQUIRE(more.size() > a.size());
  for (std::size_t k = 0; k < a.size(); ++k) CHECK(more[k].cx == a[k].cx);
  CHECK(placeCrystals(800e-6, 400e-6, 0.0, 3).empty());
}
