// The dynamic fracture scenes of 001 Sec. 6 behind the Runner face: each advance integrates one
// communication interval with the scene's time integrator, as many internal steps as it needs.
//
// How the grid parameters map onto the scenes (cell-centred lattices, 001 Sec. 4: every node is the
// centre of an h x h cell, so nx nodes span Lx with h = Lx/nx, unlike the vertex grids of scenes 1-4):
//   h = Lx/nx = Ly/ny, horizon eps = deltaOverH h; jitter must be 0.
//   5 Plexiglass crack (001 Sec. 6.1): D = [0, Lx]^2 (nx = ny), pre-crack Lx/5 from the bottom centre
//     (0.02 m at Lx = 0.1 m), collars eps thick, so deltaOverH must be a whole number. The paper's runs:
//     Lx = 0.1 m, eps = 8, 4, 2 mm, h = eps/2, eps/4, eps/8 (e.g. nx = 50, deltaOverH = 4: eps = 8 mm).
//   6, 7 bending (001 Sec. 6.2): D = [0, Lx] x [0, Ly]; pre-cracks, supports and load band sit where
//     bending_test.hpp puts them on the 0.25 x 0.05 m beam, scaled by Lx/0.25 in x and Ly/0.05 in y.
//   9 specimen with the dynamic model: its own vertex grid and grips (scenes/dynamic_specimen.cpp).
// loadFactor scales the loads from each communication point on: the pull velocity of the Plexiglass
// strips (1 m/s at loadFactor 1) and the bending body force f_max t. The material is that of 001 Table 1
// from poissonRatio (0.25 in the paper), bulkModulus, criticalEnergyReleaseRate and density.
// The scene's clock starts at 0 with the run (t in the loads of 001 is the time since loading began,
// whatever the importer's startTime) and advances by each communication step size.
#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "models/state_based_material.hpp"
#include "scenes/bending_test.hpp"
#include "scenes/fracture_diagnostics.hpp"
#include "scenes/plexiglass_crack.hpp"
#include "scenes/scene_runner.hpp"
#include "solvers/time_integrator.hpp"

namespace peristep {
namespace {

std::string text(double x) { return numberText(x); }

constexpr double kBeamLength = 0.25, kBeamDepth = 0.05;  // the beam bending_test.hpp describes [m]

double spacing(const SceneParameters& p) { return p.grid.Lx / static_cast<double>(p.grid.nx); }

DynamicScene makeScene(const SceneParameters& p) {
  if (p.scene == SceneId::Specimen) return makeDynamicSpecimen(p);
  const StateBasedInput material = dynamicMaterial(p);
  const double h = spacing(p), eps = p.grid.deltaOverH * h;
  if (p.scene == SceneId::PlexiglassCrack) {
    PlexiglassCrackSpec s;
    s.horizon = eps;
    s.meshRatio = p.grid.deltaOverH;
    s.side = p.grid.Lx;
    s.crackLength = p.grid.Lx / 5;
    s.material = material;
    return makePlexiglassCrack(s);
  }
  BendingSpec s;
  const double sx = p.grid.Lx / kBeamLength, sy = p.grid.Ly / kBeamDepth;
  s.cracks = p.scene == SceneId::BendingOneNotch ? 1 : 2;
  s.horizon = eps;
  s.meshRatio = p.grid.deltaOverH;
  s.length = p.grid.Lx;
  s.depth = p.grid.Ly;
  s.crackLength *= sy;
  s.loadDepth *= sy;
  s.crackOffset *= sx;
  s.supportCentre *= sx;
  s.supportHalfWidth *= sx;
  s.loadHalfWidth *= sx;
  s.material = material;
  return makeBendingTest(s);
}

// The material nodes (D, collars excluded) as the cloud whose domain the outputs are written on;
// lattice nodes are numbered row by row, so D's nodes in lattice order are an [ny][nx] image. A specimen
// names its image points itself (Void ones read 0: they carry no bonds and never move).
PointCloud outputCloud(const DynamicScene& scene) {
  PointCloud c = scene.cloud;
  c.domain = scene.outputPoints;
  for (std::size_t p = 0; scene.outputPoints.empty() && p < c.size(); ++p)
    if (scene.material[p]) c.domain.push_back(p);
  return c;
}

std::vector<double> onMaterial(const PointCloud& c, const double* field, std::size_t stride, std::size_t offset) {
  std::vector<double> v;
  v.reserve(c.domain.size());
  for (std::size_t p : c.domain) v.push_back(field[stride * p + offset]);
  return v;
}

class DynamicRunner final : public Runner {
 public:
  explicit DynamicRunner(const SceneParameters& p)
      : scene_(makeScene(p)),
        output_(outputCloud(scene_)),
        diagnostics_(scene_),
        youngsModulus_(3.0 * p.bulkModulus * (1.0 - 2.0 * p.poissonRatio)),
        fixedStep_(p.timeIntegrator == TimeIntegratorKind::CentralDifference),
        maxSteps_(p.limits.internalSteps),
        progress_(p.progress) {
    IntegratorOptions o;
    o.timeStep = p.internalTimeStep > 0 ? p.internalTimeStep : scene_.timeStep;
    o.relativeTolerance = p.integratorTolerance;
    // The adaptive integrators cannot say their step count up front: they stop at the limit instead.
    if (maxSteps_ > 0) o.maxSteps = static_cast<long>(std::min<std::uint64_t>(maxSteps_, LONG_MAX));
    timeStep_ = o.timeStep;
    try {
      integrator_ = makeTimeIntegrator(p.timeIntegrator, *scene_.problem, o);
    } catch (const InvalidInput& e) {
      if (!fixedStep_) throw;
      // Central difference refuses a step above its stability limit: name the parameter behind it.
      throw InvalidInput("internalTimeStep = " + text(o.timeStep) + " s (0: the scene's step) on this lattice (h = " +
                         text(scene_.h()) + " m, horizon " + text(scene_.horizon()) + " m): " + e.what());
    }
    measure();
  }

  const PointCloud& cloud() const override { return output_; }

  void advance(const SceneInputs& in) override {
    require(std::isfinite(in.stepSize) && in.stepSize >= 0,
            "communication step size must be non-negative (got " + std::to_string(in.stepSize) + ")");
    const double steps = internalSteps(in.stepSize);
    if (fixedStep_ && maxSteps_ > 0 && steps > static_cast<double>(maxSteps_))
      throw InvalidInput("internalTimeStep " + text(timeStep_) + " s would need " + text(steps) +
                         " internal steps in this communication step of " + text(in.stepSize) +
                         " s; the limit is maxInternalSteps = " + std::to_string(maxSteps_) +
                         "; use a smaller communication step or a larger internal step");
    DynamicProblem& problem = *scene_.problem;
    if (in.loadFactor != problem.loadScale()) {
      // New loads from this communication point on; the state itself is unchanged.
      const double t = integrator_->time();
      const std::size_t n = problem.dofs();
      const std::vector<double> u(integrator_->displacement(), integrator_->displacement() + n);
      const std::vector<double> v(integrator_->velocity(), integrator_->velocity() + n);
      problem.rescaleLoads(in.loadFactor, t, u.data());
      integrator_->setState(t, u.data(), v.data(), integrator_->externalWork());
    }
    if (in.stepSize > 0) advanceBy(in.stepSize, steps);
    measure();
  }

  void measure() {
    record_ = diagnostics_.measure(*integrator_);
    if (std::all_of(scene_.grips.begin(), scene_.grips.end(), [](const auto& g) { return g.empty(); })) return;
    // A grip's force on the specimen is minus the specimen's on the collar: the internal forces among the
    // collar's own points cancel pairwise.
    std::vector<double> f(scene_.problem->dofs());
    scene_.model->force(integrator_->displacement(), f.data());
    const double V = scene_.model->pointVolume(0);
    for (std::size_t k = 0; k < 4; ++k) {
      reactions_[k] = {0.0, 0.0};
      for (std::size_t q : scene_.grips[k])
        for (std::size_t d = 0; d < 2; ++d) reactions_[k][d] -= f[2 * q + d] * V;
    }
  }

  // Central difference: whole steps plus one landing on the end (solvers/central_difference.cpp).
  double internalSteps(double stepSize) const { return std::ceil(stepSize / timeStep_ - 1e-6); }

  // A long step of the central difference goes in pieces of whole internal steps, each reported to
  // the progress hook. The pieces depend on the step count only, never on whether anyone listens, so
  // the result is the same with and without progress messages.
  void advanceBy(double stepSize, double steps) {
    const double start = integrator_->time(), end = start + stepSize;
    if (!fixedStep_ || steps <= kPieceSteps) {
      integrator_->advanceTo(end);
      return;
    }
    const double piece = std::max(kPieceSteps, std::ceil(steps / 20));
    const auto total = static_cast<std::uint64_t>(steps);
    ProgressReporter report(progress_, "internalSteps", total);
    for (double done = piece; done < steps; done += piece) {
      integrator_->advanceTo(start + done * timeStep_);
      report(static_cast<std::uint64_t>(done));
    }
    integrator_->advanceTo(end);
    report(total);
  }

  std::vector<double> ux() const override { return onMaterial(output_, integrator_->displacement(), 2, 0); }
  std::vector<double> uy() const override { return onMaterial(output_, integrator_->displacement(), 2, 1); }
  std::vector<double> youngsModulus() const override {
    if (!scene_.youngsModulus.empty()) return onMaterial(output_, scene_.youngsModulus.data(), 1, 0);
    return std::vector<double>(output_.domain.size(), youngsModulus_);
  }
  std::array<double, 2> gripReaction(Side side) const override { return reactions_[static_cast<std::size_t>(side)]; }
  // Z of 001:(104) (> 1 where the bond strain has passed the softening point).
  std::vector<double> damage() const override { return onMaterial(output_, diagnostics_.damage().data(), 1, 0); }
  double crackLength() const override { return record_.crackLength; }
  double fractureEnergy() const override { return record_.fractureEnergy; }
  double strainEnergy() const override { return record_.elastic; }
  double kineticEnergy() const override { return record_.kinetic; }
  double externalWork() const override { return record_.externalWork; }
  double forceEvaluations() const override { return static_cast<double>(integrator_->stats().forceEquivalents()); }

  // Everything the future depends on: time, u, v, the work so far and the load path (the model keeps
  // no history: Z and the energies follow from u).
  std::vector<std::uint8_t> saveState() const override {
    const std::size_t n = scene_.problem->dofs();
    const DynamicProblem::LoadPath path = scene_.problem->loadPath();
    ByteWriter w;
    w.put(integrator_->time());
    w.put(integrator_->externalWork());
    w.putArray(std::span<const double>(integrator_->displacement(), n));
    w.putArray(std::span<const double>(integrator_->velocity(), n));
    w.put(path.scale);
    w.put(path.since);
    w.putArray(path.start);
    return w.take();
  }

  void restoreState(std::span<const std::uint8_t> bytes) override {
    const std::size_t n = scene_.problem->dofs();
    ByteReader r(bytes);
    const double t = r.get<double>(), work = r.get<double>();
    const std::vector<double> u = r.getArray<double>(n), v = r.getArray<double>(n);
    DynamicProblem::LoadPath path;
    path.scale = r.get<double>();
    path.since = r.get<double>();
    path.start = r.getArray<double>(scene_.problem->prescribedDofs().size());
    r.expectEnd();
    scene_.problem->setLoadPath(path);
    integrator_->setState(t, u.data(), v.data(), work);
    measure();
  }

 private:
  DynamicScene scene_;
  PointCloud output_;
  FractureDiagnostics diagnostics_;  // refers to scene_
  double youngsModulus_;  // the 3D relation 001 Table 1 is computed with: E = 3 K (1 - 2 nu)
  static constexpr double kPieceSteps = 1000;

  bool fixedStep_;           // central difference: the step count of an interval is known up front
  std::uint64_t maxSteps_;   // 0: no limit
  ProgressHook progress_;
  double timeStep_ = 0;
  std::unique_ptr<TimeIntegrator> integrator_;
  EnergyRecord record_;
  std::array<std::array<double, 2>, 4> reactions_{};  // of the specimen's grips, by Side
};

}  // namespace

StateBasedInput dynamicMaterial(const SceneParameters& p) {
  StateBasedInput in;
  in.bulkModulus = p.bulkModulus;
  in.poissonRatio = p.poissonRatio;
  in.fractureEnergy = p.criticalEnergyReleaseRate;
  in.density = p.density;
  return in;
}

void validateDynamicScene(const SceneParameters& p) {
  const GridSpec& g = p.grid;
  if (p.scene == SceneId::Specimen)
    validate(p.specimen, g);  // the specimen's vertex grid, the same for both of its models
  else
    validate(g, GridLayout::CellCentred);
  require(g.jitter == 0, "the dynamic scenes need a lattice: jitter must be 0 (got " + std::to_string(g.jitter) + ")");
  if (p.scene == SceneId::PlexiglassCrack) {
    require(g.nx == g.ny, "the Plexiglass crack is a square: nx must equal ny (got nx = " + std::to_string(g.nx) +
                              ", ny = " + std::to_string(g.ny) + ")");
    require(std::abs(g.deltaOverH - std::round(g.deltaOverH)) < 1e-9,
            "the Plexiglass collars are one horizon thick: deltaOverH must be a whole number (got " +
                std::to_string(g.deltaOverH) + ")");
  }
  require(std::isfinite(p.internalTimeStep) && p.internalTimeStep >= 0,
          "internalTimeStep must be >= 0 s (0: the scene's step), got " + std::to_string(p.internalTimeStep));
  require(std::isfinite(p.integratorTolerance) && p.integratorTolerance > 0,
          "integratorTolerance must be positive, got " + std::to_string(p.integratorTolerance));
}

std::unique_ptr<Runner> makeDynamicRunner(const SceneParameters& p) { return std::make_unique<DynamicRunner>(p); }

}  // namespace peristep
