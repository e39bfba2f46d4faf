#pragma once
// Test 3 of 000 Sec. 4.3: a crack along a bimaterial interface, E1 = 2 + sin xi1 above, E2 = 2 + sin xi2
// below (xi1 ~ N(0,1), xi2 ~ U[-1,1]), crack faces free on y = 0, x < 0, tip at the origin; the exact
// near-tip field (complex stress intensity 1) is prescribed on the collar on all four sides. The crack does
// not grow: an elastic problem with the bonds across the crack absent.
#include <memory>
#include <vector>

#include "geometry/segments.hpp"
#include "scenes/interface_crack_field.hpp"
#include "solvers/static_lps.hpp"

namespace peristep {

// Material and exact field of Test 3 (no body force). Points within 1e-9 h of y = 0 belong to the upper
// material and crack face, as the bond cutting has them.
class InterfaceCrackExact final : public ElasticScene {
 public:
  InterfaceCrackExact(double nu, double xi1, double xi2, double h);
  double poissonRatio() const override { return nu_; }
  double youngsModulus(double, double y) const override { return y > -tiny_ ? E1_ : E2_; }
  Vec2 bodyForce(double, double) const override { return {0.0, 0.0}; }
  Vec2 displacement(double x, double y) const override;

 private:
  double nu_, E1_, E2_, tiny_;
  InterfaceCrackField field_;
};

// The crack on `grid`: along y = 0 from the collar's outer edge (2 delta beyond the left side) to the origin.
Segment interfaceCrack(const GridSpec& grid);

// Test 3 on a grid, for the convergence study (bench/test3_convergence); the FMU's interfaceCrack scene is the
// elastic specimen with exactSolution interfaceCrack and this crack (scene_model.cpp, withPreset).
class InterfaceCrackScene {
 public:
  InterfaceCrackScene(const GridSpec& grid, double nu, double xi1, double xi2,
                      LinearSolverKind solver = LinearSolverKind::Umfpack);

  // Solves with the collar at loadFactor times the exact field.
  void solve(double loadFactor = 1.0) { lps_->solve(loadFactor); }
  // sqrt(sum |u_i - s u0(x_i)|^2 h^2) over the domain points.
  double errorL2() const { return lps_->errorL2(); }
  const StaticLps& solver() const { return *lps_; }

 private:
  InterfaceCrackExact exact_;
  std::unique_ptr<StaticLps> lps_;
};

}  // namespace peristep
