#pragma once
// The sample loop of `peristep sample`: for each level of a rule, every sample is taken from the store
// or run through the component (one instance per sample, all loading increments, outputs after the
// last), then the moments of every Float64 output 000:(3.10)-(3.11) and, where the component knows the
// exact moments (Tests 1-3), the L2 errors of the mean and standard deviation of the displacement.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "result_layout.hpp"
#include "sample_plan.hpp"
#include "sample_statistics.hpp"
#include "sample_store.hpp"
#include "simulation.hpp"

namespace peristep::host {

struct LevelResult {
  std::uint64_t level = 0;
  LevelPlan plan;
  std::vector<SampleRecord> records;  // one per job, in plan order
  std::size_t computed = 0, reused = 0;
  double seconds = 0;                 // wall time of this level in this process
  Moments scalarMoments;              // over the layout's scalars
  std::vector<Moments> fieldMoments;  // one per layout field
  std::optional<double> errorMean, errorStd;  // L2 over the domain, displacement vector
  // L2 distance of the displacement's mean and standard deviation to those of the study's last level:
  // the random-space error alone, with the spatial error left out (set by compareWithLast).
  std::optional<double> diffMean, diffStd;
};

// Fills diffMean/diffStd of every level but the last.
void compareWithLast(std::vector<LevelResult>& levels, const ResultLayout& layout);

class SampleStudy {
 public:
  // componentId (e.g. SampleStore::fileDigest of the binary) enters every sample's key.
  SampleStudy(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
              const FmuInstance::Options& options, const SampleStore& store, std::string componentId);

  // Runs (or reloads) every sample of the level; `progress(done, total)` after each.
  LevelResult runLevel(const SamplingOptions& rule, const RandomSpace& space, std::uint64_t level,
                       const std::function<void(std::size_t, std::size_t)>& progress);

  // Valid once a level has run.
  const ResultLayout& layout() const { return layout_; }
  bool hasExactMoments() const { return exact_; }

 private:
  SampleRecord runSample(const Scene& scene);
  void describe(const Scene& scene);
  void finish(LevelResult& r) const;

  const FmuLibrary& library_;
  const ModelDescription& md_;
  const Scene& scene_;
  FmuInstance::Options options_;
  const SampleStore& store_;
  std::string componentId_;
  std::unique_ptr<Simulation> pending_;  // set up by describe() and not yet stepped
  std::string pendingDefinition_;
  ResultLayout layout_;
  std::vector<std::uint64_t> fieldSizes_;
  bool described_ = false, exact_ = false;
};

}  // namespace peristep::host
