// The 1D stochastic deformation-gamut bar of 002 behind the Runner face (scene gamutBar): realization
// `seed` of the bar (the realization index of the study bench/gamut_bar seeds with GamutBarSpec::seed),
// loaded one force step per call. Monotonic: the end stress follows the input, F = loadFactor sigma_f A.
// Cyclic: each fmi3DoStep takes the next force of the protocol runGamutStudy runs (cyclicForces), and the
// last one fits n' and K' from the same strains with the same functions, so both give the same numbers.
//
// The bar is not on the plate grid: the image outputs ([ny][nx]) are zero. An FMU state holds the forces
// stepped to; restoring replays them on a fresh solver, which is deterministic, so a restored state
// continues bit for bit without serializing the solver's factors and active sets.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

#include "core/byte_stream.hpp"
#include "geometry/bar_grid.hpp"
#include "scenes/cyclic_fit.hpp"
#include "scenes/gamut_loading.hpp"
#include "scenes/scene_declaration.hpp"
#include "scenes/shared_variables.hpp"
#include "scenes/scene_runner.hpp"
#include "solvers/gamut_bar_solver.hpp"

namespace peristep {
namespace {

// nx * ny image points at the origin: the fields the FMI layer reads are all zero for the bar.
PointCloud imageOnly(const GridSpec& g) {
  PointCloud c;
  c.nx = g.nx;
  c.ny = g.ny;
  const std::size_t n = g.nx * g.ny;
  c.x.assign(n, 0.0);
  c.y.assign(n, 0.0);
  c.image.resize(n);
  std::iota(c.image.begin(), c.image.end(), std::int64_t{0});
  c.domain.resize(n);
  std::iota(c.domain.begin(), c.domain.end(), std::size_t{0});
  c.region.assign(n, Region::Domain);
  return c;
}

class GamutBarRunner final : public Runner {
 public:
  explicit GamutBarRunner(const SceneParameters& p)
      : bar_(p.gamutBar, p.grid.seed), cyclic_(p.gamutCyclic), image_(imageOnly(p.grid)) {
    if (cyclic_) {
      protocol_ = gamutCyclicProtocol(bar_.spec().material);
      protocolForces_ = cyclicForces(protocol_, bar_.spec().area);
    }
    replay(false);
  }

  const PointCloud& cloud() const override { return image_; }
  std::vector<double> ux() const override { return zeros(); }
  std::vector<double> uy() const override { return zeros(); }
  std::vector<double> youngsModulus() const override { return zeros(); }

  void advance(const SceneInputs& in) override {
    double force = 0;
    if (cyclic_) {
      // A step of size 0 (initialization) reads the current state; after the protocol the bar stays.
      if (in.stepSize <= 0 || forces_.size() == protocolForces_.size()) return;
      force = protocolForces_[forces_.size()];
    } else {
      force = in.loadFactor * bar_.spec().material.failureStress * bar_.spec().area;
      if (force == solver_->force()) return;  // already in equilibrium there
    }
    forces_.push_back(force);
    try {
      stepTo(force);
    } catch (const LinearRangeExceeded&) {
      // As runGamutStudy: a realization whose local strains pass the solver's bound for the far elements
      // runs again from the start with every element free to slip.
      replay(true);
    } catch (...) {
      forces_.pop_back();  // the solver is left mid-step: rebuilt from the forces that did converge
      replay(unbounded_);
      throw;
    }
  }

  double brokenBonds() const override { return static_cast<double>(last_.brokenBonds); }
  double stress() const { return last_.stress; }
  double strain() const { return last_.strain; }
  double cyclicExponent() const { return fit_.exponent; }
  double cyclicCoefficient() const { return fit_.coefficient; }

  std::vector<std::uint8_t> saveState() const override {
    ByteWriter w;
    w.put<std::uint8_t>(unbounded_);
    w.putArray(forces_);
    return w.take();
  }
  void restoreState(std::span<const std::uint8_t> bytes) override {
    ByteReader r(bytes);
    const bool unbounded = r.get<std::uint8_t>() != 0;
    std::vector<double> forces = r.getArray<double>();
    r.expectEnd();
    if (cyclic_ && forces.size() > protocolForces_.size())
      ByteReader::corrupt("more steps than the cyclic protocol has");
    forces_ = std::move(forces);
    replay(unbounded);
  }

 private:
  std::vector<double> zeros() const { return std::vector<double>(image_.domain.size(), 0.0); }

  void stepTo(double force) {
    last_ = solver_->step(force);
    strains_.push_back(last_.strain);
    if (cyclic_ && strains_.size() == protocolForces_.size()) {
      const CyclicLoops loops = cyclicLoops(protocol_, bar_.spec().area, strains_);
      fit_ = fitCyclicCurve(loops.stressAmplitude, loops.plasticStrainAmplitude);
    }
  }

  // A fresh solver stepped through forces_ (unbounded: no linear part, linearStrain = infinity).
  void replay(bool unbounded) {
    unbounded_ = unbounded;
    solver_ = std::make_unique<GamutBarSolver>(bar_, unbounded ? std::numeric_limits<double>::infinity() : 0.0);
    strains_.clear();
    last_ = {};
    fit_ = {};
    for (double force : forces_) stepTo(force);
  }

  GamutBar bar_;
  bool cyclic_;
  PointCloud image_;
  CyclicProtocol protocol_;
  std::vector<double> protocolForces_;  // cyclic: the end force of every step of the protocol
  std::vector<double> forces_;          // the end forces stepped to so far, in order
  std::vector<double> strains_;         // the strain each of them reached
  bool unbounded_ = false;
  std::unique_ptr<GamutBarSolver> solver_;
  GamutBarOutput last_;
  CyclicFit fit_;
};

using namespace declaration_names;
constexpr ValueReference kMaterial = 110, kGrid = 111, kBonds = 112, kScatterDenominator = 113, kWeibullShape = 114,
                         kProtocol = 115, kStress = 120, kStrain = 121, kCyclicExponent = 122,
                         kCyclicCoefficient = 123;

const GamutBarRunner& bar(const Runner& r) { return static_cast<const GamutBarRunner&>(r); }

// The bar's spec from its parameters (the enumerations' values are checked when they are set).
void configure(SceneParameters& p) {
  GamutBarSpec& s = p.gamutBar;
  s.material = ownValue(p, kMaterial) == 2 ? gamutMaterial2() : gamutMaterial1();
  s.gridJitter = ownValue(p, kGrid) == 2 ? kStochasticGridJitter : 0.0;  // 002:(36)
  s.bonds = static_cast<int>(std::min(ownValue(p, kBonds), double(std::numeric_limits<int>::max())));
  s.scatter.denominator = ownValue(p, kScatterDenominator);
  s.scatter.weibullShape = ownValue(p, kWeibullShape);
  p.gamutCyclic = ownValue(p, kProtocol) == 2;
}

}  // namespace

SceneDeclaration gamutBarScene() {
  return {
      .id = SceneId::GamutBar,
      .name = "gamutBar",
      .description =
          "1D stochastic deformation-gamut bar (Desai, paper 002 Sec. 4): realization seed of gamutBonds bonds, "
          "gamutMaterial, gamutGrid, scatter of 002:(26); fixed at x = 0, pulled at x = L. gamutProtocol "
          "monotonic: every step moves the end stress to loadFactor * sigma_f; cyclic: every step of any size "
          "takes the next of the protocol's 53 force steps, and cyclicExponent, cyclicCoefficient hold n', K' "
          "after the 53rd; quasi-static, no image outputs",
      .variables = {
    {.name = "gamutMaterial", .vr = kMaterial, .type = T::Enumeration,
     .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
     .description = "gamutBar scene: the Ramberg-Osgood material of 002 Sec. 4.2",
     .declaredType = "PeriStep.GamutMaterial", .start = "1"},
    {.name = "gamutGrid", .vr = kGrid, .type = T::Enumeration, .causality = C::Parameter,
     .variability = V::Fixed, .initial = I::Exact, .description = "gamutBar scene: the grid of the bar's points",
     .declaredType = "PeriStep.GamutGrid", .start = "1"},
    {.name = "gamutBonds", .vr = kBonds, .type = T::UInt64, .causality = C::Parameter,
     .variability = V::Fixed, .initial = I::Exact,
     .description = "gamutBar scene: local bonds of the bar (bonds + 1 points, every pair interacting), >= 4",
     .start = "500", .min = Bound{4}, .max = Bound{20000}},
    {.name = "scatterDenominator", .vr = kScatterDenominator, .type = T::Float64,
     .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
     .description = "gamutBar scene: the denominator of 002:(26), M = Mbar (1 + sign W / denominator), W "
                    "Weibull(1, weibullShape) per point and bond; 10: an RMS scatter of 10% at shape 2, > 0",
     .start = "10", .min = Bound{0, true}},
    {.name = "weibullShape", .vr = kWeibullShape, .type = T::Float64, .causality = C::Parameter,
     .variability = V::Fixed, .initial = I::Exact,
     .description = "gamutBar scene: shape of the Weibull draw W of 002:(26) (scale 1), > 0", .start = "2",
     .min = Bound{0, true}},
    {.name = "gamutProtocol", .vr = kProtocol, .type = T::Enumeration,
     .causality = C::Parameter, .variability = V::Fixed, .initial = I::Exact,
     .description = "gamutBar scene: how the bar is loaded", .declaredType = "PeriStep.GamutProtocol",
     .start = "1"},
    {.name = "barStress", .vr = kStress, .type = T::Float64, .causality = C::Output,
     .variability = V::Continuous, .initial = I::Calculated,
     .description = "gamutBar scene: end force over area F / A after the last step; 0 otherwise", .unit = "Pa",
     .dependencies = onLoadFactor()},
    {.name = "barStrain", .vr = kStrain, .type = T::Float64, .causality = C::Output,
     .variability = V::Continuous, .initial = I::Calculated,
     .description = "gamutBar scene: end displacement over length u(L) / L after the last step; 0 otherwise",
     .dependencies = onLoadFactor()},
    {.name = "cyclicExponent", .vr = kCyclicExponent, .type = T::Float64, .causality = C::Output,
     .variability = V::Continuous, .initial = I::Calculated,
     .description = "gamutBar scene, cyclic protocol: n' of sigma_a = K' eps_pa^n' fitted to the stable loops "
                    "(002 Sec. 4.4.3) once the protocol's last step is done; 0 before that, in monotonic "
                    "loading and in the other scenes",
     .dependencies = onNoInput()},
    {.name = "cyclicCoefficient", .vr = kCyclicCoefficient, .type = T::Float64,
     .causality = C::Output, .variability = V::Continuous, .initial = I::Calculated,
     .description = "gamutBar scene, cyclic protocol: K' of the same fit once the protocol's last step is done; 0 "
                    "before that, in monotonic loading and in the other scenes",
     .unit = "Pa", .dependencies = onNoInput()},
      },
      .enumerations = {
    {"PeriStep.GamutMaterial",
     "Ramberg-Osgood materials of paper 002 Sec. 4.2",
     {{"material1", 1, "Material 1: E 71.6 GPa, sigma_y 538.6 MPa, sigma_f 665.8 MPa"},
      {"material2", 2, "Material 2: E 115.7 GPa, sigma_y 867 MPa, sigma_f 933 MPa"}},
     "PERISTEP_GAMUT_"},
    {"PeriStep.GamutGrid",
     "Grids of the gamutBar scene",
     {{"uniform", 1, "Equally spaced points"},
      {"stochastic", 2, "The stochastic grid of 002:(36)"}},
     "PERISTEP_GAMUT_GRID_"},
    {"PeriStep.GamutProtocol",
     "Loading of the gamutBar scene",
     {{"monotonic", 1, "Every step moves the end stress to loadFactor * sigma_f"},
      {"cyclic", 2,
       "Fully reversed stress-controlled cycles at 6 amplitudes from sigma_y to sigma_f, 4 steps per half "
       "cycle (53 steps, the input unused); then n' and K'"}},
     "PERISTEP_GAMUT_"},
      },
      .outputs = {{kStress, [](const Runner& r) { return bar(r).stress(); }},
                  {kStrain, [](const Runner& r) { return bar(r).strain(); }},
                  {kCyclicExponent, [](const Runner& r) { return bar(r).cyclicExponent(); }},
                  {kCyclicCoefficient, [](const Runner& r) { return bar(r).cyclicCoefficient(); }}},
      .configure = configure,
      .validate = [](const SceneParameters&) {},  // the bar checks its own spec
      .make = [](const SceneParameters& p) -> std::unique_ptr<Runner> { return std::make_unique<GamutBarRunner>(p); },
  };
}

}  // namespace peristep
