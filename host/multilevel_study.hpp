#pragma once
// `peristep sample --rule mlmc`: multilevel Monte Carlo (Giles 2008) of one scalar output over grids.
// Level 0 is the coarsest grid, the last the scene's own; each coarser grid halves nx - 1 and ny - 1.
// Level l > 0 runs pairs: the same random input (xi, or the seed of a realization) on grid l and on grid
// l - 1, and averages Q_l - Q_(l-1); level 0 averages Q_0. Levels draw from disjoint seeds, so their
// estimates are independent. A pilot of samples per level gives variances and costs; the counts then
// grow to Giles' optimum for the requested standard error until no level needs more.
// Every sample lives in the study's sample store (sample_store.hpp): a restart recomputes none, and MPI
// ranks or a rerun make the same decisions from the same stored values and times.
#include <cstdint>
#include <string>
#include <vector>

#include "mpi_session.hpp"
#include "sample_study.hpp"
#include "sampling/multilevel.hpp"

namespace peristep::host {

struct MultilevelOptions {
  std::size_t grids = 3;
  std::string quantity;         // scalar Float64 output
  double relativeSe = 0.02;     // target standard error over |estimate|, used when absoluteSe is 0
  double absoluteSe = 0;
  std::size_t pilot = 10;       // samples per level before counts are chosen, and the least per level
  std::uint64_t seed = 1;       // level l draws from seed + l * kMaxPlannedSamples on
  std::vector<double> costs;    // cost per sample of each level for the allocation; empty: measured
};

struct MultilevelLevel {
  std::uint64_t nx = 0, ny = 0;               // the level's fine grid
  std::vector<double> fine, coarse;           // Q_l and Q_(l-1) of the successful pairs (coarse: empty at 0)
  std::vector<SampleFailure> failures;        // pairs left out (either sample refused)
  double fineSeconds = 0, coarseSeconds = 0;  // mean wall time per sample on each grid
  sampling::LevelStatistics difference;       // of Y_l = Q_l - Q_(l-1) (Q_0 at level 0)
  sampling::LevelStatistics quantity;         // of Q_l
  std::size_t planned = 0;                    // pairs run (successful and failed)
};

struct MultilevelResult {
  std::string quantity, unit;
  std::vector<MultilevelLevel> levels;
  sampling::MultilevelEstimate estimate;
  double targetSe = 0;
  std::size_t rounds = 0;
  std::uint64_t computed = 0;  // samples computed by this run (all ranks), the rest came from the store
  // Plain Monte Carlo on the finest grid to the same standard error: samples and seconds, from the finest
  // level's variance of Q and its time per sample.
  double plainSamples = 0, plainSeconds = 0;
};

// The scene on the grid of `level` of `grids` (InputError when nx - 1 or ny - 1 does not halve).
Scene sceneOnGrid(const Scene& scene, const ModelDescription& md, std::size_t grids, std::size_t level,
                  std::uint64_t& nx, std::uint64_t& ny);

// Runs the study; the result is complete on rank 0 only.
MultilevelResult runMultilevel(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
                               const FmuInstance::Options& instance, const SampleStore& store,
                               const std::string& componentId, const RandomSpace& space,
                               const MultilevelOptions& options, const MpiSession& mpi);

// Per level: grid, pairs, failed, moments of Q and Y, seconds; and a one-row summary beside it.
void writeMultilevelCsv(const std::filesystem::path& levels, const std::filesystem::path& summary,
                        const MultilevelResult& result);
void printMultilevel(std::ostream& out, const MultilevelResult& result);

}  // namespace peristep::host
