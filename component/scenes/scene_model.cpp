#include "scenes/scene_model.hpp"

#include <cmath>
#include <cstring>

#include "core/errors.hpp"
#include "models/lps_material.hpp"
#include "scenes/manufactured.hpp"
#include "solvers/linear_solver.hpp"
#include "solvers/static_lps.hpp"

namespace peristep {

std::size_t sceneModes(SceneId scene) { return scene == SceneId::Smooth ? 1 : 2; }

XiDistribution xiDistribution(SceneId, std::size_t) { return XiDistribution::Normal; }

double xiScale(SceneId scene, std::size_t) { return scene == SceneId::Smooth ? 0.1 : 1.0; }

void validate(const SceneParameters& p) {
  require(p.scene == SceneId::Smooth || p.scene == SceneId::Composite,
          "unknown scene " + std::to_string(static_cast<std::int64_t>(p.scene)));
  validate(p.grid);
  validateElastic(1.0, p.poissonRatio);
  require(std::isfinite(p.modulusContrast) && p.modulusContrast > 0,
          "modulusContrast must be positive and finite (got " + std::to_string(p.modulusContrast) + ")");
  const std::size_t needed = sceneModes(p.scene);
  require(p.xi.size() >= needed, "scene needs " + std::to_string(needed) + " random coordinates but nModes = " +
                                     std::to_string(p.xi.size()));
  for (std::size_t k = 0; k < p.xi.size(); ++k)
    require(std::isfinite(p.xi[k]), "xi[" + std::to_string(k) + "] is not finite");
  makeLinearSolver(p.linearSolver);  // throws on an unknown name
}

struct SceneModel::Impl {
  std::unique_ptr<ElasticScene> scene;
  std::unique_ptr<StaticLps> lps;
  std::vector<double> x, y, ux, uy, damage;
  double load = 0;
};

SceneModel::SceneModel(const SceneParameters& p) : impl_(std::make_unique<Impl>()) {
  validate(p);
  Impl& m = *impl_;
  const auto physical = [&](std::size_t k) { return xiScale(p.scene, k) * p.xi[k]; };
  if (p.scene == SceneId::Smooth)
    m.scene = std::make_unique<SmoothScene>(p.poissonRatio, physical(0));
  else
    m.scene = std::make_unique<CompositeScene>(p.poissonRatio, physical(0), physical(1), p.modulusContrast);
  auto disc = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(p.grid));
  m.lps = std::make_unique<StaticLps>(disc, *m.scene, p.linearSolver);
  const PointCloud& c = disc->cloud;
  for (std::size_t q : c.domain) {
    m.x.push_back(c.x[q]);
    m.y.push_back(c.y[q]);
  }
  m.ux.assign(c.domain.size(), 0.0);
  m.uy.assign(c.domain.size(), 0.0);
  m.damage.assign(c.domain.size(), 0.0);
}

SceneModel::~SceneModel() = default;

void SceneModel::advance(double loadFactor) {
  impl_->lps->solve(loadFactor);
  impl_->ux = impl_->lps->ux();
  impl_->uy = impl_->lps->uy();
  impl_->load = loadFactor;
}

const std::vector<double>& SceneModel::x() const { return impl_->x; }
const std::vector<double>& SceneModel::y() const { return impl_->y; }
const std::vector<double>& SceneModel::ux() const { return impl_->ux; }
const std::vector<double>& SceneModel::uy() const { return impl_->uy; }
const std::vector<double>& SceneModel::damage() const { return impl_->damage; }
double SceneModel::loadFactor() const { return impl_->load; }
double SceneModel::errorL2() const { return impl_->lps->errorL2At(impl_->ux, impl_->uy, impl_->load); }

std::vector<std::uint8_t> SceneModel::saveState() const {
  const Impl& m = *impl_;
  std::vector<double> flat{m.load};
  flat.insert(flat.end(), m.ux.begin(), m.ux.end());
  flat.insert(flat.end(), m.uy.begin(), m.uy.end());
  std::vector<std::uint8_t> bytes(flat.size() * sizeof(double));
  std::memcpy(bytes.data(), flat.data(), bytes.size());
  return bytes;
}

void SceneModel::restoreState(std::span<const std::uint8_t> bytes) {
  Impl& m = *impl_;
  const std::size_t n = m.ux.size();
  require(bytes.size() == (1 + 2 * n) * sizeof(double),
          "state of " + std::to_string(bytes.size()) + " bytes does not belong to this scene (expected " +
              std::to_string((1 + 2 * n) * sizeof(double)) + ")");
  std::vector<double> flat(1 + 2 * n);
  std::memcpy(flat.data(), bytes.data(), bytes.size());
  m.load = flat[0];
  m.ux.assign(flat.begin() + 1, flat.begin() + 1 + static_cast<std::ptrdiff_t>(n));
  m.uy.assign(flat.begin() + 1 + static_cast<std::ptrdiff_t>(n), flat.end());
}

}  // namespace peristep
