// The quasi-static specimen behind the Runner face (the importer's specimen and the glassCeramic scene, a
// preset of it): the plate's cloud with a collar beside each held side, Void where the material map is 0
// (and beside free sides), the material of the maps (times a KL factor with a random field) or the
// glass-ceramic generator's, bonds crossing a pre-crack broken, and the quasi-static fracture driver moving
// the held collars by the load input.
#include "fracture/bond_state.hpp"
#include "scenes/crack_toughness.hpp"
#include "scenes/fracture_specimen.hpp"
#include "scenes/glass_ceramic_material.hpp"
#include "scenes/map_material.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {
namespace {

class SpecimenRunner final : public Runner {
 public:
  explicit SpecimenRunner(const SceneParameters& p) : load_(p.specimen.load) {
    const SpecimenSpec& s = p.specimen;
    PointCloud cloud = specimenCloud(s, p.grid);
    if (s.material == SpecimenMaterial::GlassCeramic) {
      CrystalField field = crystalField(cloud, p);
      const PhaseConstants phases = phaseConstants(p);
      const PointMaterial m = phaseMaterial(cloud, field.R, phases);
      b_ = buildFractureSpecimen(s, std::move(cloud), m, p.linearSolver);
      // 000 Sec. 5's measurements, of the crack grown from the first pre-crack's end.
      const Segment tip = s.cracks.empty() ? Segment{} : s.cracks.front();
      const double tipX = s.cracks.empty() ? -0.5 * p.grid.Lx : tip.x1;
      toughness_ = std::make_unique<CrackToughness>(*b_.fracture, tipX, tip.y1, 0.5 * p.grid.Lx, m.G,
                                                    std::move(field), phases);
    } else {
      const PointMaterial m = mapMaterial(cloud, p, retainedVariance_);
      b_ = buildFractureSpecimen(s, std::move(cloud), m, p.linearSolver);
    }
    // Inside a load step the crack may run for hundreds of sub-iterations at one load: report each, and
    // the bonds broken so far in the step (open-ended counts: total 0).
    if (p.progress)
      b_.fracture->onSubIteration([hook = p.progress](const LoadStepReport& r) {
        hook("subIterations", static_cast<std::uint64_t>(r.subIterations), 0);
        hook("brokenBonds", r.newlyBroken, 0);
      });
    // The outputs cover every image point: the material ones are the cloud's domain, Void ones read 0.
    output_ = imageCloud(b_.disc->cloud);
  }
  const PointCloud& cloud() const override { return output_; }
  void advance(const SceneInputs& in) override {
    b_.fracture->advance(load_ == SpecimenLoad::LoadDisplacement ? in.loadDisplacement : in.loadFactor);
  }
  std::vector<double> ux() const override { return onImage(b_.fracture->displacement(), 2, 0); }
  std::vector<double> uy() const override { return onImage(b_.fracture->displacement(), 2, 1); }
  std::vector<double> youngsModulus() const override { return onImage(b_.E, 1, 0); }
  // 000:(3.23) on the material points; 0 on Void, where nothing can break.
  std::vector<double> damage() const override {
    const PointCloud& c = b_.disc->cloud;
    const std::vector<double> material = damageField(b_.fracture->bonds(), c, b_.disc->neighbours);
    std::vector<double> all(c.size(), 0.0);
    for (std::size_t i = 0; i < c.domain.size(); ++i) all[c.domain[i]] = material[i];
    return onImage(all, 1, 0);
  }
  double brokenBonds() const override {
    const auto& d = b_.fracture->discretization();
    return static_cast<double>(brokenPairs(b_.fracture->bonds(), d.cloud, d.neighbours));
  }
  std::array<double, 2> gripReaction(Side side) const override {
    return b_.fracture->collarForce(b_.collars[static_cast<std::size_t>(side)]);
  }
  // The glass-ceramic measurements (000 Sec. 5); the maps' specimens report their grips' reactions only.
  double reactionForce() const override { return toughness_ ? gripReaction(Side::Top)[1] : 0.0; }
  double crackLength() const override { return toughness_ ? toughness_->crackLength() : 0.0; }
  double fractureEnergy() const override {
    return toughness_ ? toughness_->energyReleaseRate() * toughness_->projectedCrackLength() : 0.0;
  }
  double toughnessKIC() const override { return toughness_ ? toughness_->toughnessKIC() : 0.0; }
  bool separated() const override { return toughness_ && toughness_->crackReachedRightEdge(); }
  std::vector<double> xiScales() const override { return toughness_ ? pcaScales(toughness_->field()) : std::vector<double>{}; }
  double retainedVariance() const override {
    const PcaModes* pca = toughness_ ? toughness_->field().pca.get() : nullptr;
    return pca ? pca->retainedFraction() : retainedVariance_;
  }
  std::vector<std::uint8_t> saveState() const override { return b_.fracture->saveState(); }
  void restoreState(std::span<const std::uint8_t> bytes) override { b_.fracture->restoreState(bytes); }

 private:
  std::vector<double> onImage(const std::vector<double>& field, std::size_t stride, std::size_t offset) const {
    return peristep::onImage(output_, field, stride, offset);
  }

  SpecimenLoad load_;
  FractureSpecimen b_;
  std::unique_ptr<CrackToughness> toughness_;  // glass-ceramic material only
  double retainedVariance_ = 1.0;              // of the KL modes, with a random field
  PointCloud output_;
};

}  // namespace

std::unique_ptr<Runner> makeSpecimenRunner(const SceneParameters& p) { return std::make_unique<SpecimenRunner>(p); }

}  // namespace peristep
