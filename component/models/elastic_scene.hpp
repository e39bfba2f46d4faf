#pragma once
// A static elastic scene: material, body force and the displacement prescribed on the collar.
#include <array>

namespace peristep {

using Vec2 = std::array<double, 2>;

class ElasticScene {
 public:
  virtual ~ElasticScene() = default;
  virtual double poissonRatio() const = 0;
  virtual double youngsModulus(double x, double y) const = 0;
  // f in 000:(2.5)
  virtual Vec2 bodyForce(double x, double y) const = 0;
  // Dirichlet data on the collar; for the manufactured scenes also the exact local solution.
  virtual Vec2 displacement(double x, double y) const = 0;
};

}  // namespace peristep
