#include "scenes/interface_crack.hpp"

#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "models/lps_material.hpp"

namespace peristep {

InterfaceCrackScene::InterfaceCrackScene(const GridSpec& grid, double nu, double xi1, double xi2,
                                         LinearSolverKind solver)
    : field_(2.0 + std::sin(xi1), 2.0 + std::sin(xi2), nu) {
  require(std::isfinite(xi1) && std::isfinite(xi2), "random coordinates xi must be finite");
  require(xi2 >= -1.0 && xi2 <= 1.0, "Test 3: xi2 is uniform on [-1, 1] (got " + std::to_string(xi2) + ")");
  disc_ = sharedDiscretization(grid);
  const PointCloud& c = disc_->cloud;
  const double tiny = 1e-9 * c.h;

  FractureMaterial m;
  std::vector<double> unit(2 * c.size(), 0.0);
  const Lame upper = planeStrain(2.0 + std::sin(xi1), nu), lower = planeStrain(2.0 + std::sin(xi2), nu);
  for (std::size_t p = 0; p < c.size(); ++p) {
    const bool above = c.y[p] > -tiny;  // points on y = 0 belong to the upper material and face
    m.lambda.push_back(above ? upper.lambda : lower.lambda);
    m.mu.push_back(above ? upper.mu : lower.mu);
    m.fractureEnergy.push_back(std::numeric_limits<double>::infinity());  // the crack does not grow
    if (!c.inDomain(p)) {
      const Vec2 u = exact(c.x[p], c.y[p]);
      unit[2 * p] = u[0];
      unit[2 * p + 1] = u[1];
    }
  }
  BondState bonds = makeBondState(c, disc_->neighbours, m.lambda, m.mu, m.fractureEnergy);
  const double far = 0.5 * static_cast<double>(c.nx - 1) * c.h + 3.0 * c.delta;
  breakCrossing(bonds, c, disc_->neighbours, {-far, 0.0, 0.0, 0.0});
  fracture_ = std::make_unique<QuasiStaticFracture>(disc_, std::move(m), std::move(bonds), std::move(unit), solver);
}

Vec2 InterfaceCrackScene::exact(double x, double y) const {
  const double tiny = 1e-9 * disc_->cloud.h;
  return field_.displacement(x, std::abs(y) <= tiny ? +0.0 : y);
}

void InterfaceCrackScene::solve(double loadFactor) { fracture_->advance(loadFactor); }

double InterfaceCrackScene::errorL2() const {
  const PointCloud& c = disc_->cloud;
  const std::vector<double>& u = fracture_->displacement();
  const double s = fracture_->load();
  double sum = 0;
  for (std::size_t p : c.domain) {
    const Vec2 e = exact(c.x[p], c.y[p]);
    const double dx = u[2 * p] - s * e[0], dy = u[2 * p + 1] - s * e[1];
    sum += dx * dx + dy * dy;
  }
  return std::sqrt(sum * c.h * c.h);
}

}  // namespace peristep
