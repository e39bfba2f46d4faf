// The dynamic fracture scenes of 001 Sec. 6 behind the Runner face: each advance integrates one
// communication interval with the scene's time integrator, as many internal steps as it needs.
//
// Every dynamic scene is a specimen with the dynamic model (scenes/dynamic_specimen.cpp): the importer's,
// or the preset of a scene of 001 Sec. 6 (scenes/plexiglass_crack.hpp, scenes/bending_test.hpp; the
// scene model applies it, withPreset), on the vertex grid of every scene (h = Lx/(nx-1); each point the
// centre of an h x h cell of material).
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
#include "scenes/fracture_diagnostics.hpp"
#include "scenes/scene_runner.hpp"
#include "solvers/time_integrator.hpp"

namespace peristep {
namespace {

std::string text(double x) { return numberText(x); }

// The specimen's image points, Void ones included (they read 0: no bonds, never moving), as the domain the
// outputs are written on.
PointCloud outputCloud(const DynamicScene& scene) {
  PointCloud c = scene.cloud;
  c.domain = scene.outputPoints;
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
      : scene_(makeDynamicSpecimen(p)),
        output_(outputCloud(scene_)),
        diagnostics_(scene_),
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
    if (std::all_of(scene_.grips.begin(), scene_.grips.end(), [](const auto& g) { return g.points.empty(); })) return;
    // A grip's force on the specimen in a held component is minus the internal force on its points (their
    // acceleration there is prescribed); the forces among a collar's own points cancel pairwise.
    std::vector<double> f(scene_.problem->dofs());
    scene_.model->force(integrator_->displacement(), f.data());
    const double V = scene_.model->pointVolume(0);
    reactions_.assign(scene_.grips.size(), {0.0, 0.0});
    for (std::size_t k = 0; k < scene_.grips.size(); ++k) {
      const DynamicScene::HeldPoints& grip = scene_.grips[k];
      for (std::size_t q : grip.points) {
        if (grip.x) reactions_[k][0] -= f[2 * q] * V;
        if (grip.y) reactions_[k][1] -= f[2 * q + 1] * V;
      }
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
  std::vector<double> youngsModulus() const override { return onMaterial(output_, scene_.youngsModulus.data(), 1, 0); }
  std::array<double, 2> gripReaction(Side side) const override { return reaction(static_cast<std::size_t>(side)); }
  std::array<double, 2> boxReaction(std::size_t box) const override { return reaction(4 + box); }
  std::array<double, 2> reaction(std::size_t grip) const {
    return grip < reactions_.size() ? reactions_[grip] : std::array<double, 2>{0.0, 0.0};
  }
  // Z of 001:(104) (> 1 where the bond strain has passed the softening point).
  std::vector<double> damage() const override { return onMaterial(output_, diagnostics_.damage().data(), 1, 0); }
  double crackLength() const override { return record_.crackLength; }
  double fractureEnergy() const override { return record_.fractureEnergy; }
  double strainEnergy() const override { return record_.elastic; }
  double kineticEnergy() const override { return record_.kinetic; }
  double externalWork() const override { return record_.externalWork; }
  // Counted over the run, so a restored state continues the count it was saved with.
  double forceEvaluations() const override {
    return evaluationsBefore_ + static_cast<double>(integrator_->stats().forceEquivalents());
  }

  // Everything the future depends on: time, u, v, the work so far and the load path (the model keeps
  // no history: Z and the energies follow from u).
  std::vector<std::uint8_t> saveState() const override {
    const std::size_t n = scene_.problem->dofs();
    const DynamicProblem::LoadPath path = scene_.problem->loadPath();
    ByteWriter w;
    w.put(integrator_->time());
    w.put(integrator_->externalWork());
    w.put(forceEvaluations());
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
    const double t = r.get<double>(), work = r.get<double>(), evaluations = r.get<double>();
    const std::vector<double> u = r.getArray<double>(n), v = r.getArray<double>(n);
    DynamicProblem::LoadPath path;
    path.scale = r.get<double>();
    path.since = r.get<double>();
    path.start = r.getArray<double>(scene_.problem->prescribedDofs().size());
    r.expectEnd();
    scene_.problem->setLoadPath(path);
    integrator_->setState(t, u.data(), v.data(), work);
    evaluationsBefore_ = evaluations - static_cast<double>(integrator_->stats().forceEquivalents());
    measure();
  }

 private:
  DynamicScene scene_;
  PointCloud output_;
  FractureDiagnostics diagnostics_;  // refers to scene_
  static constexpr double kPieceSteps = 1000;

  bool fixedStep_;           // central difference: the step count of an interval is known up front
  std::uint64_t maxSteps_;   // 0: no limit
  ProgressHook progress_;
  double timeStep_ = 0;
  std::unique_ptr<TimeIntegrator> integrator_;
  double evaluationsBefore_ = 0;  // force evaluations of the run before the integrator's own count
  EnergyRecord record_;
  std::vector<std::array<double, 2>> reactions_;  // of the specimen's grips (scene_.grips)
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
  validate(withPreset(p).specimen, g);
  require(g.jitter == 0, "the dynamic scenes need a lattice: jitter must be 0 (got " + std::to_string(g.jitter) + ")");
  if (p.scene == SceneId::PlexiglassCrack)
    require(g.nx == g.ny, "the Plexiglass crack is a square: nx must equal ny (got nx = " + std::to_string(g.nx) +
                              ", ny = " + std::to_string(g.ny) + ")");
  require(std::isfinite(p.internalTimeStep) && p.internalTimeStep >= 0,
          "internalTimeStep must be >= 0 s (0: the scene's step), got " + std::to_string(p.internalTimeStep));
  require(std::isfinite(p.integratorTolerance) && p.integratorTolerance > 0,
          "integratorTolerance must be positive, got " + std::to_string(p.integratorTolerance));
}

std::unique_ptr<Runner> makeDynamicRunner(const SceneParameters& p) { return std::make_unique<DynamicRunner>(p); }

}  // namespace peristep
