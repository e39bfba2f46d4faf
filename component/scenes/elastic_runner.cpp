// Tests 1 and 2 (000 Sec. 4.1-4.2): linear, so the factorization is computed once and every step is one solve.
#include <cmath>

#include "core/byte_stream.hpp"
#include "scenes/manufactured.hpp"
#include "scenes/scene_runner.hpp"
#include "solvers/static_lps.hpp"

namespace peristep {
namespace {

class ElasticRunner final : public Runner {
 public:
  explicit ElasticRunner(const SceneParameters& p) {
    const auto xi = [&](std::size_t k) { return xiScale(p.scene, k) * p.xi[k]; };
    if (p.scene == SceneId::Smooth)
      scene_ = std::make_unique<SmoothScene>(p.poissonRatio, xi(0));
    else
      scene_ = std::make_unique<CompositeScene>(p.poissonRatio, xi(0), xi(1), p.modulusContrast);
    lps_ = std::make_unique<StaticLps>(sharedDiscretization(p.grid), *scene_, p.linearSolver);
    ux_.assign(cloud().domain.size(), 0.0);
    uy_.assign(cloud().domain.size(), 0.0);
  }
  const PointCloud& cloud() const override { return lps_->discretization().cloud; }
  void advance(const SceneInputs& in) override {
    lps_->solve(in.loadFactor);
    ux_ = lps_->ux();
    uy_ = lps_->uy();
    load_ = in.loadFactor;
  }
  std::vector<double> ux() const override { return ux_; }
  std::vector<double> uy() const override { return uy_; }
  std::vector<double> youngsModulus() const override {
    std::vector<double> E;
    for (std::size_t q : cloud().domain) E.push_back(scene_->youngsModulus(cloud().x[q], cloud().y[q]));
    return E;
  }
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

}  // namespace

std::unique_ptr<Runner> makeElasticRunner(const SceneParameters& p) { return std::make_unique<ElasticRunner>(p); }

}  // namespace peristep
