// The pre-cracked glass-ceramic plate (000 Sec. 5) opened by the displacement input U_D; its material is
// the microstructure of a seed or, with pcaRealizations > 0, the PCA field 000:(5.5) at the coordinates xi.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <omp.h>
#include <sstream>

#include "fracture/bond_state.hpp"
#include "random/pca_cache.hpp"
#include "scenes/microstructure.hpp"
#include "scenes/glass_ceramic.hpp"
#include "scenes/scene_runner.hpp"

namespace peristep {
namespace {

// PCA of the crystal indicator over the realizations of seeds 1..n on the specimen's cloud, computed
// once per process for one cloud, fraction, n and number of modes (the samples of a study share it).
// The key holds everything the modes depend on, at full precision: the cloud (grid, horizon, jitter
// and, for a jittered cloud, its seed), the fraction, n and k.
std::shared_ptr<const PcaModes> crystalPca(const SceneParameters& p) {
  const GridSpec& g = p.grid;
  std::ostringstream key;
  key << std::hexfloat << "glassCeramic " << g.nx << 'x' << g.ny << ' ' << g.Lx << ' ' << g.Ly << ' '
      << g.deltaOverH << " jitter=" << g.jitter << " seed=" << (g.jitter == 0.0 ? 0 : g.seed)
      << " f=" << p.crystalFraction << " n=" << p.pcaRealizations << " k=" << p.xi.size();
  return cachedPca(key.str(), [&] {
    GridSpec grid = p.grid;
    grid.collar = true;
    PointCloud cloud = makeRectangle(grid);
    cloud.freeSideEdges();  // the specimen's cloud, point for point
    PcaSpec spec;
    spec.values = cloud.size();
    spec.realizations = p.pcaRealizations;
    spec.modes = p.xi.size();
    // Realizations are generated on every thread; the calling thread (0) reports the count.
    std::atomic<std::uint64_t> generated{0};
    ProgressReporter report(p.progress, "pcaRealizations", spec.realizations * (spec.powerIterations + 2));
    return streamedPca(spec, [&](std::size_t j, std::span<double> out) {
      const std::vector<std::uint8_t> R = generateMicrostructure(cloud, p.crystalFraction, 1 + j);
      std::copy(R.begin(), R.end(), out.begin());
      const std::uint64_t done = ++generated;
      if (omp_get_thread_num() == 0) report(done);
    });
  });
}

GlassCeramicSpec specimenSpec(const SceneParameters& p, const PcaModes* pca) {
  GlassCeramicSpec s;
  s.grid = p.grid;
  s.crystalFraction = p.crystalFraction;
  s.seed = p.grid.seed;
  s.linearSolver = p.linearSolver;
  s.phases = {p.glassYoungsModulus, p.crystalYoungsModulus, p.glassFractureEnergy, p.crystalFractureEnergy,
              p.poissonRatio};
  if (pca) {
    // The truncated expansion 000:(5.5) is not confined to [0, 1]: with G2/G1 = 13 a point at R < -0.09
    // would get a negative fracture energy. R is a crystal indicator (a local volume fraction), so it is
    // clipped to [0, 1], which keeps E and G between the phases' values for every xi.
    const Eigen::VectorXd R = pca->expand(p.xi);
    for (double r : R) s.crystalField.push_back(std::clamp(r, 0.0, 1.0));
  }
  return s;
}

class GlassCeramicRunner final : public Runner {
 public:
  explicit GlassCeramicRunner(const SceneParameters& p)
      : pca_(p.pcaRealizations > 0 ? crystalPca(p) : nullptr), specimen_(specimenSpec(p, pca_.get())) {
    // Inside a load step the crack may run for hundreds of sub-iterations at one load: report each, and
    // the bonds broken so far in the step (open-ended counts: total 0).
    if (p.progress)
      specimen_.onSubIteration([hook = p.progress](const LoadStepReport& r) {
        hook("subIterations", static_cast<std::uint64_t>(r.subIterations), 0);
        hook("brokenBonds", r.newlyBroken, 0);
      });
  }
  const PointCloud& cloud() const override { return specimen_.solver().discretization().cloud; }
  void advance(const SceneInputs& in) override { specimen_.advance(in.loadDisplacement); }
  std::vector<double> ux() const override { return specimen_.ux(); }
  std::vector<double> uy() const override { return specimen_.uy(); }
  std::vector<double> youngsModulus() const override { return specimen_.youngsModulus(); }
  std::vector<double> damage() const override { return specimen_.damage(); }
  double reactionForce() const override { return specimen_.reactionForce(); }
  double crackLength() const override { return specimen_.crackLength(); }
  double brokenBonds() const override {
    const auto& d = specimen_.solver().discretization();
    return static_cast<double>(brokenPairs(specimen_.solver().bonds(), d.cloud, d.neighbours));
  }
  double fractureEnergy() const override { return specimen_.energyReleaseRate() * specimen_.projectedCrackLength(); }
  double toughnessKIC() const override { return specimen_.toughnessKIC(); }
  bool separated() const override { return specimen_.crackReachedRightEdge(); }
  std::vector<std::uint8_t> saveState() const override { return specimen_.saveState(); }
  void restoreState(std::span<const std::uint8_t> b) override { specimen_.restoreState(b); }
  std::vector<double> xiScales() const override {  // xi_k = sqrt(lambda_k) eta_k (random/microstructure_pca.hpp)
    std::vector<double> s;
    if (pca_)
      for (Eigen::Index k = 0; k < pca_->variances.size(); ++k) s.push_back(std::sqrt(pca_->variances[k]));
    return s;
  }
  double retainedVariance() const override { return pca_ ? pca_->retainedFraction() : 1.0; }

 private:
  std::shared_ptr<const PcaModes> pca_;
  GlassCeramicSpecimen specimen_;
};

}  // namespace

std::unique_ptr<Runner> makeGlassCeramicRunner(const SceneParameters& p) {
  return std::make_unique<GlassCeramicRunner>(p);
}

}  // namespace peristep
