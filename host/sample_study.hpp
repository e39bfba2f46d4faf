#pragma once
// The sample loop of `peristep sample`, in two halves so that several processes can share a level:
//  - runJobs: the samples a scheduler hands this process are taken from the store or run through the
//    component (one instance per sample, all loading increments, outputs after the last) and stored;
//    a sample the component refuses (fmi3Error) is stored as failed with its message;
//  - collect: one process reads every sample of the level back from the store, in plan order, and
//    computes the moments of every Float64 output 000:(3.10)-(3.11) and, where the component knows the
//    exact moments (Tests 1-3), the L2 errors of the mean and standard deviation of the displacement.
// Whoever ran the samples, the moments are summed in the same order from the same stored doubles:
// a serial, MPI or sharded study gives the same statistics bit for bit.
#include <cstdint>
#include <functional>
#include <map>
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

struct SampleFailure {
  std::size_t index = 0;  // job index in the plan
  std::string message;    // "sample k of Q (xi = [...]): " and the component's message
};

struct LevelResult {
  std::uint64_t level = 0;
  SampleRule rule = SampleRule::Smolyak;
  LevelPlan plan;
  std::vector<SampleRecord> records;    // one per job, in plan order; NaN for the failed ones
  std::vector<SampleFailure> failures;  // in plan order
  std::size_t computed = 0, reused = 0;
  double seconds = 0;                   // wall time of this level in this process
  // Monte Carlo: over the successful samples with equal weights. Tensor and Smolyak rules: only when
  // no sample failed (a quadrature rule's weights do not allow dropping a node), NaN otherwise.
  bool momentsComputed = false;
  Moments scalarMoments;                // over the layout's scalars
  std::vector<Moments> fieldMoments;    // one per layout field
  std::optional<double> errorMean, errorStd;  // L2 over the domain, displacement vector
  // L2 distance of the displacement's mean and standard deviation to those of the study's last level:
  // the random-space error alone, with the spatial error left out (set by compareWithLast).
  std::optional<double> diffMean, diffStd;
};

// One scalar output of some of a plan's jobs, read back from the store without their fields.
struct ScalarSamples {
  std::vector<double> values, seconds;          // one per job asked for; NaN for a failed one
  std::map<std::size_t, std::string> failures;  // job index in the plan -> the component's message
};

// Fills diffMean/diffStd of every level but the last (levels whose moments were computed).
void compareWithLast(std::vector<LevelResult>& levels, const ResultLayout& layout);

// What one process did with the samples it was handed.
struct LevelWork {
  std::uint64_t computed = 0, reused = 0, failed = 0;  // failed: computed by this process and refused
};

// The next job index this process should handle, or nothing when the level is done.
using NextJob = std::function<std::optional<std::size_t>()>;

class SampleStudy {
 public:
  // componentId (e.g. SampleStore::fileDigest of the binary) enters every sample's key.
  SampleStudy(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
              const FmuInstance::Options& options, const SampleStore& store, std::string componentId);

  // Runs (or finds in the store) the jobs next() hands out; `progress(index, total)` after each.
  LevelWork runJobs(const LevelPlan& plan, const NextJob& next,
                    const std::function<void(std::size_t, std::size_t)>& progress);

  // Every sample of the plan from the store, and the statistics. RunError naming the samples that are
  // neither stored nor recorded as failed.
  LevelResult collect(LevelPlan plan, SampleRule rule, std::uint64_t level);
  // Scalar output number `scalar` of the plan's jobs from `first` on, and their wall times: for a study
  // that grows its plan round by round and needs one quantity of the new samples. RunError as collect().
  ScalarSamples collectScalar(const LevelPlan& plan, std::uint64_t level, std::size_t scalar, std::size_t first);

  // Valid once runJobs or collect has run.
  const ResultLayout& layout() const { return layout_; }
  bool hasExactMoments() const { return exact_; }

 private:
  // Job k from the store: its record, or the message of its failure; neither when it is not there.
  struct Stored {
    std::optional<SampleRecord> record;
    std::optional<std::string> failure;
  };
  Stored stored(const LevelPlan& plan, std::size_t k, bool withFields) const;
  // RunError naming the missing jobs, if any.
  void requireStored(const LevelPlan& plan, std::uint64_t level, const std::vector<std::size_t>& missing) const;
  SampleRecord runSample(const Scene& scene);
  void describe(const LevelPlan& plan);
  std::uint64_t keyOf(const SampleJob& job, Scene& scene, std::string& definition) const;
  void finish(LevelResult& r) const;

  const FmuLibrary& library_;
  const ModelDescription& md_;
  const Scene& scene_;
  FmuInstance::Options options_;
  const SampleStore& store_;
  std::string componentId_;
  Scene pendingScene_;                   // the scene pending_ refers to
  std::unique_ptr<Simulation> pending_;  // set up by describe() and not yet stepped
  std::string pendingDefinition_;
  ResultLayout layout_;
  std::vector<std::uint64_t> fieldSizes_;
  bool described_ = false, exact_ = false;
  std::uint64_t computedInProcess_ = 0;  // over all levels
};

// "sample 3 of 41 (xi = [0, 1.22], seed 7)": how messages name a job (index 0-based).
std::string describeJob(const LevelPlan& plan, std::size_t index);

}  // namespace peristep::host
