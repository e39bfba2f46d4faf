#include "scenes/scene_model.hpp"

#include <Eigen/Core>
#include <cmath>
#include <optional>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "models/lps_material.hpp"
#include "scenes/bending_test.hpp"
#include "scenes/exact_moments.hpp"
#include "scenes/glass_ceramic.hpp"
#include "scenes/glass_ceramic_material.hpp"
#include "scenes/interface_crack.hpp"
#include "scenes/kl_plate.hpp"
#include "scenes/plexiglass_crack.hpp"
#include "scenes/scene_cost.hpp"
#include "scenes/scene_declaration.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {

SceneParameters withPreset(const SceneParameters& p) {
  SceneParameters q = p;
  if (p.scene == SceneId::GlassCeramic) q.specimen = glassCeramicPreset(p.grid, GlassCeramicSpec{}.preCrackLength);
  if (p.scene == SceneId::KlPlate) q.specimen = klPlatePreset(p.grid, p.poissonRatio);
  if (p.scene == SceneId::Smooth || p.scene == SceneId::Composite || p.scene == SceneId::InterfaceCrack) {
    // Tests 1-3: the whole plate is the exact solution's (000 Sec. 4), Test 3 with its interface crack.
    q.specimen = SpecimenSpec{};
    q.specimen.model = SpecimenModel::Elastic;
    for (Grip& grip : q.specimen.grips) grip.held = true;
    q.specimen.exactSolution = exactSolution(p);
    if (p.scene == SceneId::InterfaceCrack) q.specimen.cracks = {interfaceCrack(p.grid)};
  }
  // 001 Sec. 6: the dynamic scenes, each with the paper's step unless one is set.
  const bool bending = p.scene == SceneId::BendingOneNotch || p.scene == SceneId::BendingTwoNotches;
  if (p.scene == SceneId::PlexiglassCrack) q.specimen = plexiglassCrackPreset(p.grid, dynamicMaterial(p));
  if (bending) q.specimen = bendingPreset(p.grid, p.scene == SceneId::BendingOneNotch ? 1 : 2, dynamicMaterial(p));
  if (p.internalTimeStep == 0 && (bending || p.scene == SceneId::PlexiglassCrack))
    q.internalTimeStep = bending ? kBendingTimeStep : kPlexiglassTimeStep;
  return q;
}

ExactSolution exactSolution(const SceneParameters& p) {
  switch (p.scene) {
    case SceneId::Smooth: return ExactSolution::Smooth;
    case SceneId::Composite: return ExactSolution::Composite;
    case SceneId::InterfaceCrack: return ExactSolution::InterfaceCrack;
    case SceneId::Specimen: return p.specimen.exactSolution;
    default: return ExactSolution::None;
  }
}

bool usesGlassCeramic(const SceneParameters& p) {
  return p.scene == SceneId::GlassCeramic ||
         (p.scene == SceneId::Specimen && p.specimen.material == SpecimenMaterial::GlassCeramic);
}

std::size_t randomCoordinates(const SceneParameters& p) {
  switch (p.scene) {
    case SceneId::Smooth: return 1;
    case SceneId::Composite:
    case SceneId::InterfaceCrack: return 2;
    case SceneId::KlPlate: return p.xi.size();
    case SceneId::GlassCeramic:
    case SceneId::Specimen:  // an exact solution's, the KL factor's, or the PCA field's (glass-ceramic material)
      if (exactSolution(p) != ExactSolution::None) return exactSolution(p) == ExactSolution::Smooth ? 1 : 2;
      return usesKlField(p) || (usesGlassCeramic(p) && p.pcaRealizations > 0) ? p.xi.size() : 0;
    case SceneId::PlexiglassCrack:
    case SceneId::BendingOneNotch:
    case SceneId::BendingTwoNotches:
    case SceneId::GamutBar:  // the bar's realization comes from seed
    case SceneId::LearnedFracture: return 0;
  }
  return 0;
}

bool isDynamic(const SceneParameters& p) {
  return p.scene == SceneId::PlexiglassCrack || p.scene == SceneId::BendingOneNotch ||
         p.scene == SceneId::BendingTwoNotches ||
         (p.scene == SceneId::Specimen && p.specimen.model == SpecimenModel::Dynamic);
}

bool usesKlField(const SceneParameters& p) {
  return p.scene == SceneId::KlPlate || (p.scene == SceneId::Specimen && p.specimen.material == SpecimenMaterial::KlField);
}

XiDistribution xiDistribution(const SceneParameters& p, std::size_t k) {
  if (k >= randomCoordinates(p)) return XiDistribution::Unused;
  return exactSolution(p) == ExactSolution::InterfaceCrack && k == 1 ? XiDistribution::Uniform : XiDistribution::Normal;
}

double xiScale(const SceneParameters& p, std::size_t) { return exactSolution(p) == ExactSolution::Smooth ? 0.1 : 1.0; }

void validate(const SceneParameters& p) {
  const SceneDeclaration* scene = findScene(p.scene);
  require(scene != nullptr, "unknown scene " + std::to_string(static_cast<std::int64_t>(p.scene)));
  if (isDynamic(p))
    validateDynamicScene(p);  // the specimen with the dynamic model and scenes 5-7, its presets
  else if (scene->validate)
    scene->validate(p);
  else  // the specimen and its presets
    validate(withPreset(p).specimen, p.grid);
  validateElastic(1.0, p.poissonRatio);
  require(std::isfinite(p.modulusContrast) && p.modulusContrast > 0,
          "modulusContrast must be positive and finite (got " + std::to_string(p.modulusContrast) + ")");
  require(std::isfinite(p.crystalFraction) && p.crystalFraction >= 0 && p.crystalFraction <= 1,
          "crystalFraction must lie in [0, 1] (got " + std::to_string(p.crystalFraction) + ")");
  const std::size_t needed = randomCoordinates(p);
  require(p.xi.size() >= needed, "scene needs " + std::to_string(needed) + " random coordinates but nModes = " +
                                     std::to_string(p.xi.size()));
  if (usesKlField(p)) {
    require(std::isfinite(p.correlationLength) && p.correlationLength > 0,
            "correlationLength must be positive and finite (got " + std::to_string(p.correlationLength) + ")");
    // The covariance holds fieldStd^2: below 1e-150 it underflows and the retained variance is 0/0.
    require(std::isfinite(p.fieldStd) && p.fieldStd >= 1e-150 && p.fieldStd <= 1e150,
            "fieldStd must lie in [1e-150, 1e150], where its square is a normal double (got " +
                numberText(p.fieldStd) + ")");
  }
  if (usesGlassCeramic(p)) validate(phaseConstants(p));
  if (usesGlassCeramic(p) && p.pcaRealizations > 0)
    require(p.pcaRealizations > p.xi.size(), "the PCA field needs more realizations (pcaRealizations = " +
                                                 std::to_string(p.pcaRealizations) + ") than modes (nModes = " +
                                                 std::to_string(p.xi.size()) + ")");
  for (std::size_t k = 0; k < p.xi.size(); ++k)
    require(std::isfinite(p.xi[k]), "xi[" + std::to_string(k) + "] is not finite");
  if (exactSolution(p) == ExactSolution::InterfaceCrack)
    require(std::abs(p.xi[1]) <= 1.0, "xi[1] of Test 3 is uniform on [-1, 1] (got " + std::to_string(p.xi[1]) + ")");
}

struct SceneModel::Impl {
  SceneParameters parameters;
  std::unique_ptr<Runner> runner;
  std::vector<double> x, y, ux, uy, damage, E;
  double load = 0;
  // Exact moments for load 1, computed on the first request (they cost many evaluations of u0).
  mutable std::optional<std::optional<ExactMoments>> moments;

  const std::optional<ExactMoments>& exactMoments() const {
    if (!moments) moments = peristep::exactMoments(parameters, runner->cloud());
    return *moments;
  }

  void refresh() {
    ux = runner->ux();
    uy = runner->uy();
    std::vector<double> d = runner->damage();
    if (!d.empty()) damage = std::move(d);
  }
};

SceneModel::SceneModel(const SceneParameters& p) : impl_(std::make_unique<Impl>()) {
  // Eigen splits its dense products over OpenMP threads, and the split changes their rounding: off, so a
  // scene gives the same bits on any number of threads (its own loops sum in fixed blocks). The setting
  // is this library's own (Eigen's state is not exported).
  static const bool eigenSerial = (Eigen::setNbThreads(1), true);
  (void)eigenSerial;
  validate(p);
  checkSetUpLimits(p);
  Impl& m = *impl_;
  m.parameters = p;
  if (p.progress) p.progress("setUp", 0, 1);
  m.runner = findScene(p.scene)->make(p);
  if (p.progress) p.progress("setUp", 1, 1);
  const PointCloud& cloud = m.runner->cloud();
  for (std::size_t q : cloud.domain) {
    m.x.push_back(cloud.x[q]);
    m.y.push_back(cloud.y[q]);
  }
  m.E = m.runner->youngsModulus();
  m.ux.assign(cloud.domain.size(), 0.0);
  m.uy.assign(cloud.domain.size(), 0.0);
  m.damage = m.runner->damage();
  if (m.damage.empty()) m.damage.assign(cloud.domain.size(), 0.0);
}

SceneModel::~SceneModel() = default;

void SceneModel::advance(const SceneInputs& in) {
  require(std::isfinite(in.loadFactor) && std::isfinite(in.loadDisplacement), "load inputs must be finite");
  impl_->runner->advance(in);
  impl_->refresh();
  impl_->load = in.loadFactor;
}

const std::vector<double>& SceneModel::x() const { return impl_->x; }
const std::vector<double>& SceneModel::y() const { return impl_->y; }
const std::vector<double>& SceneModel::ux() const { return impl_->ux; }
const std::vector<double>& SceneModel::uy() const { return impl_->uy; }
const std::vector<double>& SceneModel::damage() const { return impl_->damage; }
const std::vector<double>& SceneModel::youngsModulus() const { return impl_->E; }
double SceneModel::loadFactor() const { return impl_->load; }
double SceneModel::errorL2() const { return impl_->runner->errorL2(); }
bool SceneModel::hasExactMoments() const { return impl_->exactMoments().has_value(); }

std::vector<double> SceneModel::exactMoment(int which) const {
  const auto& m = impl_->exactMoments();
  if (!m) return {};
  const std::vector<double>* fields[] = {&m->meanUx, &m->meanUy, &m->stdUx, &m->stdUy};
  // u0 is linear in the load factor: the mean scales with it, the standard deviation with its size.
  const double scale = which < 2 ? impl_->load : std::abs(impl_->load);
  std::vector<double> v = *fields[which];
  for (double& e : v) e *= scale;
  return v;
}

std::vector<double> SceneModel::xiScales() const {
  std::vector<double> s = impl_->runner->xiScales();
  if (s.empty())
    for (std::size_t k = 0; k < impl_->parameters.xi.size(); ++k) s.push_back(xiScale(impl_->parameters, k));
  return s;
}

double SceneModel::retainedVariance() const { return impl_->runner->retainedVariance(); }

double SceneModel::reactionForce() const { return impl_->runner->reactionForce(); }
double SceneModel::crackLength() const { return impl_->runner->crackLength(); }
double SceneModel::brokenBonds() const { return impl_->runner->brokenBonds(); }
double SceneModel::fractureEnergy() const { return impl_->runner->fractureEnergy(); }
double SceneModel::ownOutput(ValueReference vr) const {
  for (const OwnOutput& o : findScene(impl_->parameters.scene)->outputs)
    if (o.vr == vr) return o.read(*impl_->runner);
  return 0.0;
}
double SceneModel::toughnessKIC() const { return impl_->runner->toughnessKIC(); }
bool SceneModel::separated() const { return impl_->runner->separated(); }
std::array<double, 2> SceneModel::gripReaction(Side side) const { return impl_->runner->gripReaction(side); }
std::array<double, 2> SceneModel::boxReaction(std::size_t box) const { return impl_->runner->boxReaction(box); }
double SceneModel::strainEnergy() const { return impl_->runner->strainEnergy(); }
double SceneModel::kineticEnergy() const { return impl_->runner->kineticEnergy(); }
double SceneModel::externalWork() const { return impl_->runner->externalWork(); }
double SceneModel::forceEvaluations() const { return impl_->runner->forceEvaluations(); }

std::vector<std::uint8_t> SceneModel::saveState() const {
  ByteWriter w;
  w.put(impl_->load);
  w.putArray(impl_->runner->saveState());
  return w.take();
}

void SceneModel::restoreState(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes);
  const double load = r.get<double>();
  const std::vector<std::uint8_t> inner = r.getArray<std::uint8_t>();
  r.expectEnd();
  impl_->runner->restoreState(inner);
  impl_->load = load;
  impl_->refresh();
}

}  // namespace peristep
