#pragma once
// What a sample study runs: the random space the component declares (xiDistribution), the rule's
// points and weights per level, and for each point the scene it defines.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fmu_instance.hpp"
#include "sampling/sample_set.hpp"
#include "sampling/rule1d.hpp"
#include "sampling/sparse_grid.hpp"
#include "scene_file.hpp"

namespace peristep::host {

enum class SampleRule { Tensor, Smolyak, MonteCarlo };

struct SamplingOptions {
  SampleRule rule = SampleRule::Smolyak;
  // tensor: points per coordinate; smolyak: level (0 = one point); mc: number of samples.
  std::vector<std::uint64_t> levels;
  bool nested = false;     // smolyak: the nested 1D family instead of Gauss rules
  std::uint64_t seed = 1;  // mc: seed of the coordinates, or the first microstructure seed (see below)
};

// The scene's random coordinates: which entries of xi (of nModes) are random and their laws.
struct RandomSpace {
  std::size_t nModes = 0;
  std::vector<std::size_t> index;         // entries of xi that are random
  std::vector<sampling::Law> laws;        // their standardized laws
};

// Asks the component, without building the scene: parameters set, Initialization Mode, xiDistribution.
RandomSpace readRandomSpace(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
                            const FmuInstance::Options& options);

// One sample: the full xi vector and, for Monte Carlo over a scene without random coordinates (real
// microstructures), the seed that makes its realization.
struct SampleJob {
  std::vector<double> xi;
  std::optional<std::uint64_t> seed;
};

struct LevelPlan {
  sampling::SampleSet set;     // points over the random coordinates only
  std::vector<SampleJob> jobs;  // one per point
  // Smolyak: the sparse pseudo-spectral projection on the same points (variance as a sum of squares).
  std::optional<sampling::SparseProjection> projection;
};

// A study plans at most this many samples per level; a larger plan is refused before it is built.
inline constexpr std::uint64_t kMaxPlannedSamples = 1'000'000;

// The rule's name on the command line (tensor, smolyak, mc).
std::string ruleName(SampleRule rule);

// Throws InputError for a rule the space cannot take (tensor or Smolyak without random coordinates)
// or a plan of more than kMaxPlannedSamples samples.
LevelPlan planLevel(const SamplingOptions& options, const RandomSpace& space, std::uint64_t level);

// The scene with this sample's xi (and seed); `definition` receives the text that identifies it.
Scene sceneForSample(const Scene& scene, const ModelDescription& md, const SampleJob& job, std::string& definition);

}  // namespace peristep::host
