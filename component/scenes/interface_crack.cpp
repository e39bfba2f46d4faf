#include "scenes/interface_crack.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "fracture/bond_state.hpp"

namespace peristep {

InterfaceCrackExact::InterfaceCrackExact(double nu, double xi1, double xi2, double h)
    : nu_(nu), E1_(2.0 + std::sin(xi1)), E2_(2.0 + std::sin(xi2)), tiny_(1e-9 * h), field_(E1_, E2_, nu) {
  require(std::isfinite(xi1) && std::isfinite(xi2), "random coordinates xi must be finite");
  require(xi2 >= -1.0 && xi2 <= 1.0, "Test 3: xi2 is uniform on [-1, 1] (got " + std::to_string(xi2) + ")");
}

Vec2 InterfaceCrackExact::displacement(double x, double y) const {
  return field_.displacement(x, std::abs(y) <= tiny_ ? +0.0 : y);
}

Segment interfaceCrack(const GridSpec& grid) { return {-0.5 * grid.Lx - 2.0 * grid.delta(), 0.0, 0.0, 0.0}; }

InterfaceCrackScene::InterfaceCrackScene(const GridSpec& grid, double nu, double xi1, double xi2,
                                         LinearSolverKind solver)
    : exact_(nu, xi1, xi2, grid.h()) {
  const std::shared_ptr<const LpsDiscretization> disc = sharedDiscretization(grid);
  lps_ = std::make_unique<StaticLps>(disc, exact_, solver,
                                     intactBonds(disc->cloud, disc->neighbours, {interfaceCrack(grid)}));
}

}  // namespace peristep
