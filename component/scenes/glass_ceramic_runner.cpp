// The pre-cracked glass-ceramic plate (000 Sec. 5) opened by the displacement input U_D.
#include "fracture/bond_state.hpp"
#include "scenes/glass_ceramic.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {
namespace {

GlassCeramicSpec specimenSpec(const SceneParameters& p) {
  GlassCeramicSpec s;
  s.grid = p.grid;
  s.crystalFraction = p.crystalFraction;
  s.seed = p.grid.seed;
  s.linearSolver = p.linearSolver;
  s.phases.nu = p.poissonRatio;
  return s;
}

class GlassCeramicRunner final : public Runner {
 public:
  explicit GlassCeramicRunner(const SceneParameters& p) : specimen_(specimenSpec(p)) {}
  const PointCloud& cloud() const override { return specimen_.solver().discretization().cloud; }
  void advance(const SceneInputs& in) override { specimen_.advance(in.loadDisplacement); }
  std::vector<double> ux() const override { return specimen_.ux(); }
  std::vector<double> uy() const override { return specimen_.uy(); }
  std::vector<double> youngsModulus() const override { return specimen_.youngsModulus(); }
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
  GlassCeramicSpecimen specimen_;
};

}  // namespace

std::unique_ptr<Runner> makeGlassCeramicRunner(const SceneParameters& p) {
  return std::make_unique<GlassCeramicRunner>(p);
}

}  // namespace peristep
