#include <catch2/catch.hpp>
#include <numbers>

#include "geometry/neighbours.hpp"

using namespace peristep;

namespace {

// Brute force reference, with the same inclusion of points at exactly the radius.
std::vector<std::vector<std::uint32_t>> bruteForce(const PointCloud& c, double radius) {
  std::vector<std::vector<std::uint32_t>> rows(c.size());
  const double r2 = radius * radius * (1.0 + 1e-10);
  for (std::size_t p = 0; p < c.size(); ++p)
    for (std::size_t q = 0; q < c.size(); ++q) {
      const double dx = c.x[q] - c.x[p], dy = c.y[q] - c.y[p];
      if (q != p && dx * dx + dy * dy <= r2) rows[p].push_back(static_cast<std::uint32_t>(q));
    }
  return rows;
}

void requireSameAsBruteForce(const PointCloud& c) {
  const Neighbours nb = findNeighbours(c, c.delta);
  const auto ref = bruteForce(c, c.delta);
  REQUIRE(nb.points() == c.size());
  for (std::size_t p = 0; p < c.size(); ++p) {
    const std::vector<std::uint32_t> row(nb.index.begin() + static_cast<std::ptrdiff_t>(nb.begin(p)),
                                         nb.index.begin() + static_cast<std::ptrdiff_t>(nb.end(p)));
    REQUIRE(row == ref[p]);
  }
}

}  // namespace

TEST_CASE("cell-list neighbours equal brute force, points at exactly delta included", "[geometry]") {
  GridSpec g;
  // h = pi/64 puts lattice points at exactly delta = 3h from each other where the cell boundaries
  // round badly: the case that once dropped bonds.
  g.nx = g.ny = 65;
  g.Lx = g.Ly = std::numbers::pi;
  g.deltaOverH = 3.0;
  SECTION("lattice") {
    const PointCloud c = makeRectangle(g);
    requireSameAsBruteForce(c);
    // Every point of the lattice more than delta inside the cloud has the full 28-point stencil.
    const Neighbours nb = findNeighbours(c, c.delta);
    const std::size_t side = c.nx + 2 * c.layers;
    for (std::size_t j = 3; j + 3 < side; ++j)
      for (std::size_t i = 3; i + 3 < side; ++i) REQUIRE(nb.end(j * side + i) - nb.begin(j * side + i) == 28);
  }
  SECTION("jittered cloud") {
    g.jitter = 0.2;
    requireSameAsBruteForce(makeRectangle(g));
  }
}

TEST_CASE("the collar has ceil(2 delta/h) layers and the domain keeps image order", "[geometry]") {
  GridSpec g;
  g.nx = 9;
  g.ny = 5;
  g.Lx = 2.0;
  g.Ly = 1.0;
  g.deltaOverH = 2.5;
  const PointCloud c = makeRectangle(g);
  CHECK(c.layers == 5);
  CHECK(c.size() == (9 + 10) * (5 + 10));
  REQUIRE(c.domain.size() == 45);
  for (std::size_t i = 0; i < c.domain.size(); ++i) {
    CHECK(c.image[c.domain[i]] == static_cast<std::int64_t>(i));
    CHECK(c.x[c.domain[i]] == Approx(-1.0 + 0.25 * static_cast<double>(i % 9)));
    CHECK(c.y[c.domain[i]] == Approx(-0.5 + 0.25 * static_cast<double>(i / 9)));
  }
}
