// A plate whose Young's modulus is a Karhunen-Loeve random field (000 Sec. 2.2-3.2): E = E0 (1 + g) or
// E0 exp(g - v/2) with g = sum_k sqrt(lambda_k) phi_k xi_k over the whole cloud (collar included), E0 = 1
// (dimensionless, as Tests 1-3). The collar imposes a uniaxial stretch u = loadFactor (0, 0.01 y); no
// body force. Linear: one factorization per sample, one solve per load step.
#include <cmath>
#include <unordered_map>

#include "core/byte_stream.hpp"
#include "scenes/elastic_scene.hpp"
#include "scenes/kl_material.hpp"
#include "scenes/scene_runner.hpp"
#include "solvers/static_lps.hpp"

namespace peristep {
namespace {

constexpr double kMeanModulus = 1.0;
constexpr double kStretch = 0.01;

// The material per point, found again from the point's own coordinates (StaticLps asks by position).
class KlPlateScene final : public ElasticScene {
 public:
  KlPlateScene(const PointCloud& c, std::vector<double> E, double nu) : E_(std::move(E)), nu_(nu) {
    for (std::size_t p = 0; p < c.size(); ++p) index_.emplace(key(c.x[p], c.y[p]), p);
  }
  double poissonRatio() const override { return nu_; }
  double youngsModulus(double x, double y) const override { return E_.at(index_.at(key(x, y))); }
  Vec2 bodyForce(double, double) const override { return {0.0, 0.0}; }
  Vec2 displacement(double, double y) const override { return {0.0, kStretch * y}; }

 private:
  static std::pair<double, double> key(double x, double y) { return {x, y}; }
  struct Hash {
    std::size_t operator()(const std::pair<double, double>& k) const {
      return std::hash<double>()(k.first) * 31u + std::hash<double>()(k.second);
    }
  };
  std::vector<double> E_;
  double nu_;
  std::unordered_map<std::pair<double, double>, std::size_t, Hash> index_;
};

class KlPlateRunner final : public Runner {
 public:
  explicit KlPlateRunner(const SceneParameters& p) {
    auto disc = sharedDiscretization(p.grid);
    const PointCloud& c = disc->cloud;
    const std::shared_ptr<const KlField> field = sharedKlField(c, p);
    retained_ = field->retainedVarianceFraction();
    std::vector<double> E = klMaterial(*field, kMeanModulus, p);
    for (std::size_t q : c.domain) domainE_.push_back(E[q]);
    scene_ = std::make_unique<KlPlateScene>(c, std::move(E), p.poissonRatio);
    lps_ = std::make_unique<StaticLps>(disc, *scene_, p.linearSolver);
    ux_.assign(c.domain.size(), 0.0);
    uy_.assign(c.domain.size(), 0.0);
  }
  const PointCloud& cloud() const override { return lps_->discretization().cloud; }
  void advance(const SceneInputs& in) override {
    lps_->solve(in.loadFactor);
    ux_ = lps_->ux();
    uy_ = lps_->uy();
  }
  std::vector<double> ux() const override { return ux_; }
  std::vector<double> uy() const override { return uy_; }
  std::vector<double> youngsModulus() const override { return domainE_; }
  double retainedVariance() const override { return retained_; }
  std::vector<std::uint8_t> saveState() const override {
    ByteWriter w;
    w.putArray(ux_);
    w.putArray(uy_);
    return w.take();
  }
  void restoreState(std::span<const std::uint8_t> bytes) override {
    ByteReader r(bytes);
    auto ux = r.getArray<double>(ux_.size());
    auto uy = r.getArray<double>(uy_.size());
    r.expectEnd();
    ux_ = std::move(ux);
    uy_ = std::move(uy);
  }

 private:
  std::unique_ptr<KlPlateScene> scene_;
  std::unique_ptr<StaticLps> lps_;
  std::vector<double> ux_, uy_, domainE_;
  double retained_ = 1.0;
};

}  // namespace

std::unique_ptr<Runner> makeKlPlateRunner(const SceneParameters& p) { return std::make_unique<KlPlateRunner>(p); }

}  // namespace peristep
