#include "scenes/manufactured.hpp"

#include <cmath>

#include "models/lps_material.hpp"
#include "scenes/interface_crack.hpp"

namespace peristep {

SmoothScene::SmoothScene(double nu, double xi) : nu_(nu), s_(2.0 + std::sin(5.0 * xi)) {
  validateElastic(1.0, nu);
  require(std::isfinite(xi), "random coordinate xi must be finite");
}

double SmoothScene::youngsModulus(double x, double y) const { return (2.0 + std::sin(x) * std::sin(y)) * s_; }

Vec2 SmoothScene::displacement(double x, double y) const {
  return {std::sin(x) * std::sin(y) / s_, -std::cos(x) * std::cos(y) / s_};
}

Vec2 SmoothScene::bodyForce(double x, double y) const {
  // sigma = e (C1 tr(eps) I + 2 C2 eps) with e = 2 + sin x sin y and eps the strain of
  // U = (sin x sin y, -cos x cos y): eps11 = eps22 = cos x sin y, eps12 = sin x cos y (S cancels).
  const double c1 = nu_ / ((1 + nu_) * (1 - 2 * nu_)), c2 = 1 / (2 * (1 + nu_));
  const double sx = std::sin(x), cx = std::cos(x), sy = std::sin(y), cy = std::cos(y);
  const double e = 2 + sx * sy, ex = cx * sy, ey = sx * cy;  // e and its derivatives
  const double d11x = 2 * (c1 + c2) * (ex * cx * sy - e * sx * sy);  // d/dx sigma11
  const double d22y = 2 * (c1 + c2) * (ey * cx * sy + e * cx * cy);  // d/dy sigma22
  const double d12x = 2 * c2 * (ex * sx * cy + e * cx * cy);         // d/dx sigma12
  const double d12y = 2 * c2 * (ey * sx * cy - e * sx * sy);         // d/dy sigma12
  return {-(d11x + d12y), -(d12x + d22y)};
}

CompositeScene::CompositeScene(double nu, double xi1, double xi2, double contrast)
    : nu_(nu), s_(3.0 + std::sin(xi1) + std::sin(xi2)), contrast_(contrast) {
  validateElastic(1.0, nu);
  require(std::isfinite(xi1) && std::isfinite(xi2), "random coordinates xi must be finite");
  require(std::isfinite(contrast) && contrast > 0, "modulus contrast must be positive");
}

// Points on the interface (x = 0 up to round-off of the grid coordinates) take the left material.
double CompositeScene::youngsModulus(double x, double) const { return x < 1e-9 ? s_ : contrast_ * s_; }

Vec2 CompositeScene::displacement(double x, double) const {
  const double scale = x < 1e-9 ? s_ : contrast_ * s_;
  return {3 * x / scale, -x / scale};
}

std::unique_ptr<ElasticScene> manufacturedScene(ExactSolution which, double nu, const std::vector<double>& xi,
                                                double contrast, double h) {
  if (which == ExactSolution::Smooth) return std::make_unique<SmoothScene>(nu, xi.at(0));
  if (which == ExactSolution::InterfaceCrack) return std::make_unique<InterfaceCrackExact>(nu, xi.at(0), xi.at(1), h);
  return std::make_unique<CompositeScene>(nu, xi.at(0), xi.at(1), contrast);
}

}  // namespace peristep
