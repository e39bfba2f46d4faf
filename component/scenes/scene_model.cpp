#include "scenes/scene_model.hpp"

#include <cmath>
#include <functional>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "fracture/bond_state.hpp"
#include "models/lps_material.hpp"
#include "scenes/glass_ceramic.hpp"
#include "scenes/interface_crack.hpp"
#include "scenes/manufactured.hpp"
#include "solvers/linear_solver.hpp"
#include "solvers/static_lps.hpp"

namespace peristep {

std::size_t sceneModes(SceneId scene) {
  switch (scene) {
    case SceneId::Smooth: return 1;
    case SceneId::Composite:
    case SceneId::InterfaceCrack: return 2;
    case SceneId::GlassCeramic: return 0;
  }
  return 0;
}

XiDistribution xiDistribution(SceneId scene, std::size_t k) {
  return scene == SceneId::InterfaceCrack && k == 1 ? XiDistribution::Uniform : XiDistribution::Normal;
}

double xiScale(SceneId scene, std::size_t) { return scene == SceneId::Smooth ? 0.1 : 1.0; }

void validate(const SceneParameters& p) {
  require(p.scene == SceneId::Smooth || p.scene == SceneId::Composite || p.scene == SceneId::InterfaceCrack ||
              p.scene == SceneId::GlassCeramic,
          "unknown scene " + std::to_string(static_cast<std::int64_t>(p.scene)));
  validate(p.grid);
  validateElastic(1.0, p.poissonRatio);
  require(std::isfinite(p.modulusContrast) && p.modulusContrast > 0,
          "modulusContrast must be positive and finite (got " + std::to_string(p.modulusContrast) + ")");
  require(std::isfinite(p.crystalFraction) && p.crystalFraction >= 0 && p.crystalFraction <= 1,
          "crystalFraction must lie in [0, 1] (got " + std::to_string(p.crystalFraction) + ")");
  const std::size_t needed = sceneModes(p.scene);
  require(p.xi.size() >= needed, "scene needs " + std::to_string(needed) + " random coordinates but nModes = " +
                                     std::to_string(p.xi.size()));
  for (std::size_t k = 0; k < p.xi.size(); ++k)
    require(std::isfinite(p.xi[k]), "xi[" + std::to_string(k) + "] is not finite");
  if (p.scene == SceneId::InterfaceCrack)
    require(std::abs(p.xi[1]) <= 1.0, "xi[1] of Test 3 is uniform on [-1, 1] (got " + std::to_string(p.xi[1]) + ")");
  makeLinearSolver(p.linearSolver);  // throws on an unknown name
}

namespace {

// One scene behind a common face; SceneModel keeps the fields the FMI layer reads.
class Runner {
 public:
  virtual ~Runner() = default;
  virtual void advance(const SceneInputs& in) = 0;
  virtual std::vector<double> ux() const = 0;
  virtual std::vector<double> uy() const = 0;
  virtual std::vector<double> damage() const { return {}; }
  virtual double errorL2() const { return 0.0; }
  virtual double reactionForce() const { return 0.0; }
  virtual double crackLength() const { return 0.0; }
  virtual double brokenBonds() const { return 0.0; }
  virtual double fractureEnergy() const { return 0.0; }
  virtual double toughnessKIC() const { return 0.0; }
  virtual std::vector<std::uint8_t> saveState() const = 0;
  virtual void restoreState(std::span<const std::uint8_t> bytes) = 0;
};

// Tests 1 and 2: linear, so the factorization is computed once and every step is one solve.
class StaticRunner final : public Runner {
 public:
  StaticRunner(const SceneParameters& p, const std::function<double(std::size_t)>& xi) {
    if (p.scene == SceneId::Smooth)
      scene_ = std::make_unique<SmoothScene>(p.poissonRatio, xi(0));
    else
      scene_ = std::make_unique<CompositeScene>(p.poissonRatio, xi(0), xi(1), p.modulusContrast);
    auto disc = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(p.grid));
    lps_ = std::make_unique<StaticLps>(disc, *scene_, p.linearSolver);
    const std::size_t n = disc->cloud.domain.size();
    ux_.assign(n, 0.0);
    uy_.assign(n, 0.0);
  }
  const ElasticScene& scene() const { return *scene_; }
  const PointCloud& cloud() const { return lps_->discretization().cloud; }
  void advance(const SceneInputs& in) override {
    lps_->solve(in.loadFactor);
    ux_ = lps_->ux();
    uy_ = lps_->uy();
    load_ = in.loadFactor;
  }
  std::vector<double> ux() const override { return ux_; }
  std::vector<double> uy() const override { return uy_; }
  double errorL2() const override { return lps_->errorL2At(ux_, uy_, load_); }
  std::vector<std::uint8_t> saveState() const override {
    ByteWriter w;
    w.put(load_);
    w.putArray(ux_);
    w.putArray(uy_);
    return w.take();
  }
  void restoreState(std::span<const std::uint8_t> bytes) override {
    ByteReader r(bytes);
    const double load = r.get<double>();
    auto ux = r.getArray<double>(ux_.size());
    auto uy = r.getArray<double>(uy_.size());
    r.expectEnd();
    load_ = load;
    ux_ = std::move(ux);
    uy_ = std::move(uy);
  }

 private:
  std::unique_ptr<ElasticScene> scene_;
  std::unique_ptr<StaticLps> lps_;
  std::vector<double> ux_, uy_;
  double load_ = 0;
};

std::vector<double> onDomain(const PointCloud& c, const std::vector<double>& u, int component) {
  std::vector<double> v;
  v.reserve(c.domain.size());
  for (std::size_t p : c.domain) v.push_back(u[2 * p + static_cast<std::size_t>(component)]);
  return v;
}

class InterfaceCrackRunner final : public Runner {
 public:
  InterfaceCrackRunner(const SceneParameters& p, const std::function<double(std::size_t)>& xi)
      : scene_(p.grid, p.poissonRatio, xi(0), xi(1), p.linearSolver) {}
  const PointCloud& cloud() const { return scene_.solver().discretization().cloud; }
  void advance(const SceneInputs& in) override { scene_.solve(in.loadFactor); }
  std::vector<double> ux() const override { return onDomain(cloud(), scene_.solver().displacement(), 0); }
  std::vector<double> uy() const override { return onDomain(cloud(), scene_.solver().displacement(), 1); }
  std::vector<double> damage() const override {
    const auto& d = scene_.solver().discretization();
    return damageField(scene_.solver().bonds(), d.cloud, d.neighbours);
  }
  double errorL2() const override { return scene_.errorL2(); }
  double brokenBonds() const override {
    const auto& d = scene_.solver().discretization();
    return static_cast<double>(brokenPairs(scene_.solver().bonds(), d.cloud, d.neighbours));
  }
  std::vector<std::uint8_t> saveState() const override { return scene_.saveState(); }
  void restoreState(std::span<const std::uint8_t> b) override { scene_.restoreState(b); }

 private:
  InterfaceCrackScene scene_;
};

class GlassCeramicRunner final : public Runner {
 public:
  explicit GlassCeramicRunner(const SceneParameters& p) : specimen_(spec(p)) {}
  const GlassCeramicSpecimen& specimen() const { return specimen_; }
  void advance(const SceneInputs& in) override { specimen_.advance(in.loadDisplacement); }
  std::vector<double> ux() const override { return specimen_.ux(); }
  std::vector<double> uy() const override { return specimen_.uy(); }
  std::vector<double> damage() const override { return specimen_.damage(); }
  double reactionForce() const override { return specimen_.reactionForce(); }
  double crackLength() const override { return specimen_.crackShares().total(); }
  double brokenBonds() const override {
    const auto& d = specimen_.solver().discretization();
    return static_cast<double>(brokenPairs(specimen_.solver().bonds(), d.cloud, d.neighbours));
  }
  double fractureEnergy() const override { return specimen_.energyReleaseRate() * specimen_.projectedCrackLength(); }
  double toughnessKIC() const override { return specimen_.toughnessKIC(); }
  std::vector<std::uint8_t> saveState() const override { return specimen_.saveState(); }
  void restoreState(std::span<const std::uint8_t> b) override { specimen_.restoreState(b); }

 private:
  static GlassCeramicSpec spec(const SceneParameters& p) {
    GlassCeramicSpec s;
    s.grid = p.grid;
    s.crystalFraction = p.crystalFraction;
    s.seed = p.grid.seed;
    s.linearSolver = p.linearSolver;
    s.phases.nu = p.poissonRatio;
    return s;
  }
  GlassCeramicSpecimen specimen_;
};

}  // namespace

struct SceneModel::Impl {
  std::unique_ptr<Runner> runner;
  std::vector<double> x, y, ux, uy, damage, E;
  double load = 0;

  void refresh() {
    ux = runner->ux();
    uy = runner->uy();
    std::vector<double> d = runner->damage();
    if (!d.empty()) damage = std::move(d);
  }
};

SceneModel::SceneModel(const SceneParameters& p) : impl_(std::make_unique<Impl>()) {
  validate(p);
  Impl& m = *impl_;
  const std::function<double(std::size_t)> physical = [&](std::size_t k) { return xiScale(p.scene, k) * p.xi[k]; };
  const PointCloud* cloud = nullptr;
  if (p.scene == SceneId::Smooth || p.scene == SceneId::Composite) {
    auto r = std::make_unique<StaticRunner>(p, physical);
    cloud = &r->cloud();
    for (std::size_t q : cloud->domain) m.E.push_back(r->scene().youngsModulus(cloud->x[q], cloud->y[q]));
    m.runner = std::move(r);
  } else if (p.scene == SceneId::InterfaceCrack) {
    auto r = std::make_unique<InterfaceCrackRunner>(p, physical);
    cloud = &r->cloud();
    for (std::size_t q : cloud->domain) m.E.push_back(cloud->y[q] > -1e-9 * cloud->h ? 2 + std::sin(physical(0)) : 2 + std::sin(physical(1)));
    m.runner = std::move(r);
  } else {
    auto r = std::make_unique<GlassCeramicRunner>(p);
    cloud = &r->specimen().solver().discretization().cloud;
    m.E = r->specimen().youngsModulus();
    m.runner = std::move(r);
  }
  for (std::size_t q : cloud->domain) {
    m.x.push_back(cloud->x[q]);
    m.y.push_back(cloud->y[q]);
  }
  m.ux.assign(cloud->domain.size(), 0.0);
  m.uy.assign(cloud->domain.size(), 0.0);
  m.damage = m.runner->damage();
  if (m.damage.empty()) m.damage.assign(cloud->domain.size(), 0.0);
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
double SceneModel::reactionForce() const { return impl_->runner->reactionForce(); }
double SceneModel::crackLength() const { return impl_->runner->crackLength(); }
double SceneModel::brokenBonds() const { return impl_->runner->brokenBonds(); }
double SceneModel::fractureEnergy() const { return impl_->runner->fractureEnergy(); }
double SceneModel::toughnessKIC() const { return impl_->runner->toughnessKIC(); }

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
