// The specimen with the elastic model behind the Runner face (the importer's specimen and the scenes that
// are presets of it: Tests 1 and 2, the KL plate): quasi-static LPS without fracture on the specimen's
// cloud. Bonds to Void and across pre-cracks are absent from the start; nothing else of the fracture
// machinery is built (no bond states, no critical stretches): one factorization, one solve per step. With
// an exact solution the material, body force and collar data are the manufactured solution's.
#include <algorithm>

#include "core/byte_stream.hpp"
#include "fracture/bond_state.hpp"
#include "models/lps_material.hpp"
#include "scenes/glass_ceramic_material.hpp"
#include "scenes/manufactured.hpp"
#include "scenes/map_material.hpp"
#include "scenes/scene_runner.hpp"
#include "solvers/static_lps.hpp"

namespace peristep {
namespace {

bool hasVoid(const PointCloud& c) {
  return std::any_of(c.region.begin(), c.region.end(), [](Region r) { return r == Region::Void; });
}

// The grid with its full collar: the discretization a sample loop shares.
std::shared_ptr<const LpsDiscretization> fullCollar(const GridSpec& grid) {
  GridSpec g = grid;
  g.collar = true;
  return sharedDiscretization(g);
}

// Without Void the specimen's cloud is the grid's with its full collar.
std::shared_ptr<const LpsDiscretization> discretization(PointCloud cloud, const GridSpec& grid) {
  return hasVoid(cloud) ? specimenDiscretization(std::move(cloud)) : fullCollar(grid);
}

class ElasticSpecimenRunner final : public Runner {
 public:
  explicit ElasticSpecimenRunner(const SceneParameters& p) : input_(p.specimen.load) {
    const SpecimenSpec& s = p.specimen;
    if (s.exactSolution != ExactSolution::None) {
      std::vector<double> xi;
      for (std::size_t k = 0; k < randomCoordinates(p); ++k) xi.push_back(xiScale(p, k) * p.xi[k]);
      exact_ = manufacturedScene(s.exactSolution, p.poissonRatio, xi, p.modulusContrast, p.grid.h());
      // The exact solution's material and collar data everywhere: the maps' Void does not apply.
      const std::shared_ptr<const LpsDiscretization> disc = fullCollar(p.grid);
      std::vector<std::uint8_t> intact;
      if (!s.cracks.empty()) intact = intactBonds(disc->cloud, disc->neighbours, s.cracks);
      lps_ = std::make_unique<StaticLps>(disc, *exact_, p.linearSolver, std::move(intact));
      const PointCloud& c = lps_->discretization().cloud;
      for (std::size_t q = 0; q < c.size(); ++q) E_.push_back(exact_->youngsModulus(c.x[q], c.y[q]));
      finish(collarMotion(s, c).collars);
      return;
    }
    const std::shared_ptr<const LpsDiscretization> disc = discretization(specimenCloud(s, p.grid), p.grid);
    const PointCloud& c = disc->cloud;
    PointMaterial m;
    if (s.material == SpecimenMaterial::GlassCeramic) {  // 000 Sec. 5's phases on every point
      CrystalField field = crystalField(c, p);
      m = phaseMaterial(c, field.R, phaseConstants(p));
      xiScales_ = pcaScales(field);
      if (field.pca) retainedVariance_ = field.pca->retainedFraction();
    } else {
      m = mapMaterial(c, p, retainedVariance_);
    }
    StaticLoading loading;
    for (std::size_t q = 0; q < c.size(); ++q) {
      const Lame l = planeStrain(m.E[q], m.nu[q]);
      loading.lambda.push_back(l.lambda);
      loading.mu.push_back(l.mu);
    }
    CollarMotion motion = collarMotion(s, c);
    loading.unitCollar = std::move(motion.unit);
    if (hasVoid(c) || !s.cracks.empty()) loading.intact = intactBonds(c, disc->neighbours, s.cracks);
    E_ = m.E;
    lps_ = std::make_unique<StaticLps>(disc, std::move(loading), p.linearSolver);
    finish(std::move(motion.collars));
  }
  const PointCloud& cloud() const override { return output_; }
  void advance(const SceneInputs& in) override {
    load_ = input_ == SpecimenLoad::LoadDisplacement ? in.loadDisplacement : in.loadFactor;
    lps_->solve(load_);
    u_ = lps_->displacement();
    reactions_ = {};
    for (std::size_t k = 0; k < 4; ++k)
      if (std::any_of(collars_[k].begin(), collars_[k].end(), [](std::uint8_t v) { return v != 0; }))
        reactions_[k] = lps_->collarForce(collars_[k]);
  }
  std::vector<double> ux() const override { return onImage(output_, u_, 2, 0); }
  std::vector<double> uy() const override { return onImage(output_, u_, 2, 1); }
  std::vector<double> youngsModulus() const override { return onImage(output_, E_, 1, 0); }
  std::array<double, 2> gripReaction(Side side) const override { return reactions_[static_cast<std::size_t>(side)]; }
  double errorL2() const override { return exact_ ? lps_->errorL2At(ux(), uy(), load_) : 0.0; }
  // The pre-cracks' bonds (bonds to Void are no material's): 000:(3.23) and their count, fixed at set-up.
  std::vector<double> damage() const override { return damage_; }
  double brokenBonds() const override { return brokenBonds_; }
  std::vector<double> xiScales() const override { return xiScales_; }
  double retainedVariance() const override { return retainedVariance_; }
  // The solution is a function of the load alone: the state is the load, the displacement and the reactions.
  std::vector<std::uint8_t> saveState() const override {
    ByteWriter w;
    w.put(load_);
    w.putArray(u_);
    for (const auto& r : reactions_) w.put(r);
    return w.take();
  }
  void restoreState(std::span<const std::uint8_t> bytes) override {
    ByteReader r(bytes);
    const double load = r.get<double>();
    auto u = r.getArray<double>(u_.size());
    std::array<std::array<double, 2>, 4> reactions{};
    for (auto& v : reactions) v = r.get<std::array<double, 2>>();
    r.expectEnd();
    load_ = load;
    u_ = std::move(u);
    reactions_ = reactions;
  }

 private:
  void finish(std::array<std::vector<std::uint8_t>, 4> collars) {
    collars_ = std::move(collars);
    const LpsDiscretization& d = lps_->discretization();
    output_ = imageCloud(d.cloud);
    u_.assign(2 * output_.size(), 0.0);
    if (lps_->intact().empty()) return;
    std::vector<double> all(d.cloud.size(), 0.0);
    const std::vector<double> material = damageField(lps_->intact(), d.cloud, d.neighbours);
    for (std::size_t i = 0; i < d.cloud.domain.size(); ++i) all[d.cloud.domain[i]] = material[i];
    damage_ = onImage(output_, all, 1, 0);
    brokenBonds_ = static_cast<double>(brokenPairs(lps_->intact(), d.cloud, d.neighbours));
  }

  SpecimenLoad input_;
  double load_ = 0;
  std::unique_ptr<ElasticScene> exact_;  // Tests 1 and 2
  std::unique_ptr<StaticLps> lps_;
  std::array<std::vector<std::uint8_t>, 4> collars_;
  std::vector<double> E_, u_;
  std::vector<double> damage_;  // empty without pre-cracks or Void: zeros
  double brokenBonds_ = 0;
  std::array<std::array<double, 2>, 4> reactions_{};
  double retainedVariance_ = 1.0;  // of the KL or PCA modes, with a random field
  std::vector<double> xiScales_;   // of the PCA field
  PointCloud output_;
};

}  // namespace

std::unique_ptr<Runner> makeElasticSpecimenRunner(const SceneParameters& p) {
  return std::make_unique<ElasticSpecimenRunner>(p);
}

}  // namespace peristep
