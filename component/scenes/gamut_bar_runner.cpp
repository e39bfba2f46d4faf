// The 1D stochastic deformation-gamut bar of 002 behind the Runner face (scene gamutBar): realization
// `seed` of the bar (the realization index of the study bench/gamut_bar seeds with GamutBarSpec::seed),
// loaded one force step per call. Monotonic: the end stress follows the input, F = loadFactor sigma_f A.
// Cyclic: each fmi3DoStep takes the next force of the protocol runGamutStudy runs (cyclicForces), and the
// last one fits n' and K' from the same strains with the same functions, so both give the same numbers.
//
// The bar is not on the plate grid: the image outputs ([ny][nx]) are zero. An FMU state holds the forces
// stepped to; restoring replays them on a fresh solver, which is deterministic, so a restored state
// continues bit for bit without serializing the solver's factors and active sets.
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

#include "core/byte_stream.hpp"
#include "scenes/cyclic_fit.hpp"
#include "scenes/gamut_loading.hpp"
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
  double barStress() const override { return last_.stress; }
  double barStrain() const override { return last_.strain; }
  double cyclicExponent() const override { return fit_.exponent; }
  double cyclicCoefficient() const override { return fit_.coefficient; }

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

}  // namespace

std::unique_ptr<Runner> makeGamutBarRunner(const SceneParameters& p) { return std::make_unique<GamutBarRunner>(p); }

}  // namespace peristep
