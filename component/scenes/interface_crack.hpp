#pragma once
// Test 3 of 000 Sec. 4.3: a crack along a bimaterial interface, E1 = 2 + sin xi1 above, E2 = 2 + sin xi2
// below (xi1 ~ N(0,1), xi2 ~ U[-1,1]), crack faces free on y = 0, x < 0, tip at the origin; the exact
// near-tip field (complex stress intensity 1) is prescribed on the collar on all four sides.
#include <memory>
#include <string>
#include <vector>

#include "scenes/interface_crack_field.hpp"
#include "solvers/quasi_static_fracture.hpp"

namespace peristep {

class InterfaceCrackScene {
 public:
  InterfaceCrackScene(const GridSpec& grid, double nu, double xi1, double xi2,
                      LinearSolverKind solver = LinearSolverKind::Umfpack);

  // Solves with the collar at loadFactor times the exact field (the crack does not grow).
  void solve(double loadFactor = 1.0);
  // sqrt(sum |u_i - s u0(x_i)|^2 h^2) over the domain points.
  double errorL2() const;
  const QuasiStaticFracture& solver() const { return *fracture_; }
  std::vector<std::uint8_t> saveState() const { return fracture_->saveState(); }
  void restoreState(std::span<const std::uint8_t> b) { fracture_->restoreState(b); }
  // Exact field at a point; points on the crack line belong to the upper face (as the bond cutting does).
  Vec2 exact(double x, double y) const;

 private:
  InterfaceCrackField field_;
  std::shared_ptr<const LpsDiscretization> disc_;
  std::unique_ptr<QuasiStaticFracture> fracture_;
};

}  // namespace peristep
