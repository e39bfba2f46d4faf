#include <catch2/catch.hpp>

#include <cmath>

#include "scenes/crack_zone.hpp"
#include "scenes/plexiglass_crack.hpp"

using namespace peristep;

TEST_CASE("crack bands: rows, extent and width of a pre-crack's Z > 1 zone beyond its tip", "[dynamics]") {
  // eps = 8 mm, h = 4 mm; pre-crack on the middle node column up to 20 mm above the bottom face. Below,
  // (x, y) are measured from the square's lower left corner.
  PlexiglassCrackSpec spec;
  spec.meshRatio = 2;
  const DynamicScene scene = makePlexiglassCrack(spec);
  const double h = scene.h(), corner = -0.05, xc = scene.cracks[0].x1 - corner, tip = scene.cracks[0].y1 - corner;
  REQUIRE(h == Approx(4e-3));
  REQUIRE(tip == Approx(0.02));
  std::vector<double> Z(scene.cloud.size(), 0.0);
  for (std::size_t p = 0; p < Z.size(); ++p) {
    const double x = scene.cloud.x[p] - corner, y = scene.cloud.y[p] - corner;
    if (std::abs(x - xc) < 1.01 * h && y > 0 && y < tip + 16e-3) Z[p] = 2;  // three columns, rows 22-34 mm
    if (std::abs(x - 0.09) < 1e-3 && std::abs(y - 0.082) < 1e-3) Z[p] = 5;   // damage not connected to the crack
  }
  const std::vector<int> owner = crackZoneOwners(scene, Z);
  for (std::size_t p = 0; p < Z.size(); ++p) CHECK(owner[p] == (Z[p] == 2 ? 0 : -1));

  const std::vector<std::vector<CrackBandRow>> bands = crackBands(scene, Z);
  REQUIRE(bands.size() == 1);
  REQUIRE(bands[0].size() == 4);  // rows y = 22, 26, 30, 34 mm; those below the tip are not growth
  for (std::size_t k = 0; k < 4; ++k) {
    const CrackBandRow& r = bands[0][k];
    CHECK(r.advance == Approx(2e-3 + 4e-3 * static_cast<double>(k)));
    CHECK(r.points == 3);
    CHECK(r.left == Approx(-h));  // the crack points up: its left is -x
    CHECK(r.right == Approx(h));
    CHECK(r.width(h) == Approx(3 * h));
  }
}
