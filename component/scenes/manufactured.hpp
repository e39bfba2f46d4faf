#pragma once
// Scenes with an exact local solution: 000 Sec. 4.1 (Test 1) and 000 Sec. 4.2 (Test 2).
#include <array>
#include <memory>
#include <vector>

#include "core/option_table.hpp"
#include "models/elastic_scene.hpp"

namespace peristep {

// The exact solutions of 000 Sec. 4 (below and scenes/interface_crack.hpp) as a specimen's material, body force and
// collar data, with errorL2 against them: Tests 1-3 are presets of the elastic specimen with these.
enum class ExactSolution { None, Smooth, Composite, InterfaceCrack };

inline constexpr std::array<Option<ExactSolution>, 4> kExactSolutionOptions{{
    {ExactSolution::None, "none", "the maps, grips and no body force"},
    {ExactSolution::Smooth, "smooth",
     "000 Test 1: E = (2 + sin x sin y)(2 + sin 5 xi), u0 = (sin x sin y, -cos x cos y)/(2 + sin 5 xi), f = "
     "-div sigma(u0); xi = 0.1 xi[0]"},
    {ExactSolution::Composite, "composite",
     "000 Test 2: E = S left of x = 0 and modulusContrast S right of it, S = 3 + sin xi[0] + sin xi[1], u0 = "
     "(3x, -x)/E, no body force"},
    {ExactSolution::InterfaceCrack, "interfaceCrack",
     "000 Test 3: E1 = 2 + sin xi[0] above y = 0, E2 = 2 + sin xi[1] below (xi[1] in [-1, 1]), the exact near-tip "
     "field of the interface crack on y = 0, x < 0 (give that crack as a pre-crack), no body force"},
}};

// Test 1: E = (2 + sin x sin y)(2 + sin 5 xi), u0 = (sin x sin y, -cos x cos y)/(2 + sin 5 xi),
// f = -div sigma(u0) (the printed formula is +div sigma, see DESIGN 5.1); f does not depend on xi.
class SmoothScene final : public ElasticScene {
 public:
  SmoothScene(double nu, double xi);
  double poissonRatio() const override { return nu_; }
  double youngsModulus(double x, double y) const override;
  Vec2 bodyForce(double x, double y) const override;
  Vec2 displacement(double x, double y) const override;

 private:
  double nu_, s_;  // s_ = 2 + sin(5 xi)
};

// Test 2 with the corrected displacement of DESIGN 5.4: S = 3 + sin xi1 + sin xi2,
// E = S for x < 0 and contrast*S for x >= 0 (the paper has contrast = 2), f = 0,
// u0 = (3x, -x)/S on the left and (3x, -x)/(contrast*S) on the right: traction and displacement are
// continuous across x = 0.
class CompositeScene final : public ElasticScene {
 public:
  CompositeScene(double nu, double xi1, double xi2, double contrast = 2.0);
  double poissonRatio() const override { return nu_; }
  double youngsModulus(double x, double y) const override;
  Vec2 bodyForce(double, double) const override { return {0.0, 0.0}; }
  Vec2 displacement(double x, double y) const override;

 private:
  double nu_, s_, contrast_;
};

// The scene of an exact solution (not None) at physical random coordinates xi (Smooth reads xi[0], the
// others xi[0] and xi[1]) on a grid of spacing h.
std::unique_ptr<ElasticScene> manufacturedScene(ExactSolution which, double nu, const std::vector<double>& xi,
                                                double contrast, double h);

}  // namespace peristep
