#include "scenes/glass_ceramic_material.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <omp.h>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/progress.hpp"
#include "models/lps_material.hpp"
#include "random/pca_cache.hpp"
#include "scenes/microstructure.hpp"
#include "scenes/scene_model.hpp"

namespace peristep {
namespace {

// FNV-1a 64 of the cloud's regions: a specimen's Void (holes, free sides) changes the cloud the
// realizations are drawn on.
std::uint64_t regionHash(const PointCloud& c) {
  std::uint64_t h = 1469598103934665603ull;
  for (Region r : c.region) h = (h ^ static_cast<std::uint64_t>(r)) * 1099511628211ull;
  return h;
}

// PCA of the crystal indicator over the realizations of seeds 1..n on the specimen's cloud, computed
// once per process for one cloud, fraction, n and number of modes (the samples of a study share it).
// The key holds everything the modes depend on, at full precision: the cloud (grid, horizon, jitter
// and, for a jittered cloud, its seed; its regions), the fraction, n and k.
std::shared_ptr<const PcaModes> crystalPca(const PointCloud& cloud, const SceneParameters& p) {
  const GridSpec& g = p.grid;
  std::ostringstream key;
  key << std::hexfloat << "glassCeramic " << g.nx << 'x' << g.ny << ' ' << g.Lx << ' ' << g.Ly << ' '
      << g.deltaOverH << " jitter=" << g.jitter << " seed=" << (g.jitter == 0.0 ? 0 : g.seed)
      << " regions=" << regionHash(cloud) << " f=" << p.crystalFraction << " n=" << p.pcaRealizations
      << " k=" << p.xi.size();
  return cachedPca(key.str(), [&] {
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

}  // namespace

CrystalField microstructureField(const PointCloud& c, double fraction, std::uint64_t seed) {
  CrystalField f;
  f.crystal = generateMicrostructure(c, fraction, seed);
  f.R.assign(f.crystal.begin(), f.crystal.end());
  f.fraction = crystalFraction(c, f.crystal);
  return f;
}

CrystalField givenField(const PointCloud& c, std::vector<double> R) {
  require(R.size() == c.size(), "crystal field has " + std::to_string(R.size()) + " values for " +
                                    std::to_string(c.size()) + " points");
  CrystalField f;
  f.R = std::move(R);
  for (double r : f.R) f.crystal.push_back(r >= 0.5);
  for (std::size_t p : c.domain) f.fraction += f.R[p] / static_cast<double>(c.domain.size());
  return f;
}

CrystalField crystalField(const PointCloud& c, const SceneParameters& p) {
  if (p.pcaRealizations == 0) return microstructureField(c, p.crystalFraction, p.grid.seed);
  std::shared_ptr<const PcaModes> pca = crystalPca(c, p);
  // The truncated expansion 000:(5.5) is not confined to [0, 1]: with G2/G1 = 13 a point at R < -0.09
  // would get a negative fracture energy. R is a crystal indicator (a local volume fraction), so it is
  // clipped to [0, 1], which keeps E and G between the phases' values for every xi.
  std::vector<double> R;
  for (double r : pca->expand(p.xi)) R.push_back(std::clamp(r, 0.0, 1.0));
  CrystalField f = givenField(c, std::move(R));
  f.pca = std::move(pca);
  return f;
}

PhaseConstants phaseConstants(const SceneParameters& p) {
  return {p.glassYoungsModulus, p.crystalYoungsModulus, p.glassFractureEnergy, p.crystalFractureEnergy,
          p.poissonRatio};
}

void validate(const PhaseConstants& m) {
  validateElastic(m.E1, m.nu);
  validateElastic(m.E2, m.nu);
  require(m.G1 > 0 && m.G2 > 0 && std::isfinite(m.G1) && std::isfinite(m.G2), "fracture energies must be positive");
}

PointMaterial phaseMaterial(const PointCloud& c, const std::vector<double>& R, const PhaseConstants& m) {
  PointMaterial mat;
  for (std::size_t p = 0; p < c.size(); ++p) {  // 000:(5.5): E and G affine in R
    const double E = m.E1 + R[p] * (m.E2 - m.E1), G = m.G1 + R[p] * (m.G2 - m.G1);
    if (!(E > 0 && G > 0))
      throw InvalidInput("crystal field R = " + std::to_string(R[p]) + " at (x, y) = (" + std::to_string(c.x[p]) +
                         ", " + std::to_string(c.y[p]) + ") gives E = " + std::to_string(E) + " Pa, G = " +
                         std::to_string(G) + " J/m^2: not positive (a coordinate too far in the tail)");
    mat.E.push_back(E);
    mat.nu.push_back(m.nu);
    mat.G.push_back(G);
  }
  return mat;
}

std::vector<double> pcaScales(const CrystalField& field) {
  std::vector<double> scales;
  if (field.pca)
    for (Eigen::Index k = 0; k < field.pca->variances.size(); ++k) scales.push_back(std::sqrt(field.pca->variances[k]));
  return scales;
}

}  // namespace peristep
