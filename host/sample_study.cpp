#include "sample_study.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "host_errors.hpp"

namespace peristep::host {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::size_t fieldIndex(const ResultLayout& layout, const std::string& name) {
  for (std::size_t i = 0; i < layout.fields.size(); ++i)
    if (layout.fields[i].name == name) return i;
  throw RunError("the component has no output field " + name);
}

// sqrt(h^2 sum_i |a_i - b_i|^2) over the two displacement components, h the grid spacing.
double gridSpacing(const ResultLayout& layout) {
  for (std::size_t i = 0; i < layout.constantArrays.size(); ++i)
    if (layout.constantArrays[i].name == "x" && layout.nx > 1)
      return std::abs(layout.constantValues[i][1] - layout.constantValues[i][0]);
  return 1.0;
}

double l2Error(const std::vector<double>& ax, const std::vector<double>& ay, const std::vector<double>& bx,
               const std::vector<double>& by, double h) {
  double sum = 0;
  for (std::size_t i = 0; i < ax.size(); ++i) sum += (ax[i] - bx[i]) * (ax[i] - bx[i]) + (ay[i] - by[i]) * (ay[i] - by[i]);
  return std::sqrt(sum * h * h);
}

}  // namespace

SampleStudy::SampleStudy(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
                         const FmuInstance::Options& options, const SampleStore& store, std::string componentId)
    : library_(library), md_(md), scene_(scene), options_(options), store_(store), componentId_(std::move(componentId)) {}

void SampleStudy::describe(const LevelPlan& plan) {
  if (described_) return;
  keyOf(plan.jobs.front(), pendingScene_, pendingDefinition_);
  pending_ = std::make_unique<Simulation>(library_, md_, pendingScene_, options_);
  layout_ = pending_->layout();
  for (const ArrayInfo& f : layout_.fields) fieldSizes_.push_back(elementCount(f.shape));
  exact_ = md_.find("hasExactMoments") && pending_->readInteger("hasExactMoments") == 1;
  described_ = true;
}

std::uint64_t SampleStudy::keyOf(const SampleJob& job, Scene& scene, std::string& definition) const {
  scene = sceneForSample(scene_, md_, job, definition);
  return SampleStore::key(componentId_ + '|' + definition);
}

SampleRecord SampleStudy::runSample(const Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<Simulation> sim = std::move(pending_);
  if (!sim) sim = std::make_unique<Simulation>(library_, md_, scene, options_);
  StepValues last;
  for (const Increment& inc : sim->schedule()) {
    if (!sim->mayContinue()) break;
    last = sim->step(inc);
  }
  sim->terminate();
  for (double v : last.scalars)
    if (!std::isfinite(v)) throw RunError("a sample produced a non-finite output");
  SampleRecord r{std::move(last.scalars), std::move(last.fields), 0.0};
  r.seconds = secondsSince(start);
  return r;
}

std::string describeJob(const LevelPlan& plan, std::size_t index) {
  const SampleJob& job = plan.jobs[index];
  std::string xi;
  char buf[32];
  for (double v : job.xi) {
    std::snprintf(buf, sizeof buf, "%.6g", v + 0.0);  // + 0.0: no "-0" for the nodes on an axis
    xi += (xi.empty() ? "" : ", ") + std::string(buf);
  }
  return "sample " + std::to_string(index + 1) + " of " + std::to_string(plan.jobs.size()) + " (xi = [" + xi + "]" +
         (job.seed ? ", seed " + std::to_string(*job.seed) : "") + ")";
}

namespace {

// Test hook: PERISTEP_SAMPLE_EXIT_AFTER=K ends the process abruptly (as a kill would) after it has
// computed K samples, so that the tests can interrupt a study at a known point, under mpirun too.
void exitIfAsked(std::uint64_t computed) {
  static const char* limit = std::getenv("PERISTEP_SAMPLE_EXIT_AFTER");
  if (limit && computed >= std::strtoull(limit, nullptr, 10)) std::_Exit(137);  // as after SIGKILL
}

}  // namespace

LevelWork SampleStudy::runJobs(const LevelPlan& plan, const NextJob& next,
                               const std::function<void(std::size_t, std::size_t)>& progress) {
  LevelWork work;
  describe(plan);
  while (const std::optional<std::size_t> index = next()) {
    Scene scene;
    std::string definition;
    const std::uint64_t key = keyOf(plan.jobs.at(*index), scene, definition);
    if (store_.failure(key) || store_.load(key, layout_.scalars.size(), fieldSizes_, false)) {
      ++work.reused;
    } else {
      if (pending_ && pendingDefinition_ != definition) pending_.reset();
      std::optional<SampleRecord> record;
      try {
        record = runSample(scene);
      } catch (const RunError& e) {  // the component refused this sample: recorded, the study goes on
        pending_.reset();
        store_.saveFailure(key, e.what());
        ++work.failed;
      }
      if (record) store_.save(key, *record);  // outside the try: a store that cannot write ends the study
      ++work.computed;
      exitIfAsked(++computedInProcess_);
    }
    if (progress) progress(*index + 1, plan.jobs.size());
  }
  pending_.reset();
  return work;
}

SampleStudy::Stored SampleStudy::stored(const LevelPlan& plan, std::size_t k, bool withFields) const {
  Scene scene;
  std::string definition;
  const std::uint64_t key = keyOf(plan.jobs[k], scene, definition);
  Stored s;
  if ((s.record = store_.load(key, layout_.scalars.size(), fieldSizes_, withFields))) return s;
  s.failure = store_.failure(key);
  return s;
}

void SampleStudy::requireStored(const LevelPlan& plan, std::uint64_t level, const std::vector<std::size_t>& missing) const {
  if (missing.empty()) return;
  std::string list;
  for (std::size_t k : missing) list += (list.empty() ? "" : ", ") + std::to_string(k + 1);
  throw RunError("level " + std::to_string(level) + ": " + std::to_string(missing.size()) + " of " +
                 std::to_string(plan.jobs.size()) + " samples are not in " + store_.directory().string() +
                 ": samples " + list + " (first: " + describeJob(plan, missing.front()) +
                 "); run the shards or the study that computes them first");
}

LevelResult SampleStudy::collect(LevelPlan plan, SampleRule rule, std::uint64_t level) {
  describe(plan);
  LevelResult r;
  r.level = level;
  r.rule = rule;
  r.plan = std::move(plan);
  std::vector<std::size_t> missing;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < r.plan.jobs.size(); ++k) {
    Stored s = stored(r.plan, k, true);
    if (s.record) {
      r.records.push_back(std::move(*s.record));
      continue;
    }
    if (s.failure) {
      r.failures.push_back({k, describeJob(r.plan, k) + ": " + *s.failure});
    } else {
      missing.push_back(k);
    }
    SampleRecord empty{std::vector<double>(layout_.scalars.size(), nan), {}, nan};
    for (std::uint64_t n : fieldSizes_) empty.fields.emplace_back(n, nan);
    r.records.push_back(std::move(empty));
  }
  requireStored(r.plan, level, missing);
  finish(r);
  return r;
}

ScalarSamples SampleStudy::collectScalar(const LevelPlan& plan, std::uint64_t level, std::size_t scalar,
                                         std::size_t first) {
  describe(plan);
  ScalarSamples out;
  std::vector<std::size_t> missing;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = first; k < plan.jobs.size(); ++k) {
    const Stored s = stored(plan, k, false);
    out.values.push_back(s.record ? s.record->scalars.at(scalar) : nan);
    out.seconds.push_back(s.record ? s.record->seconds : nan);
    if (s.failure) out.failures.emplace(k, *s.failure);
    else if (!s.record) missing.push_back(k);
  }
  requireStored(plan, level, missing);
  return out;
}

void SampleStudy::finish(LevelResult& r) const {
  const bool monteCarlo = r.rule == SampleRule::MonteCarlo;
  r.momentsComputed = r.failures.size() < r.records.size() && (monteCarlo || r.failures.empty());
  std::vector<std::size_t> used;  // the successful samples, in plan order
  for (std::size_t k = 0, f = 0; k < r.records.size(); ++k)
    if (f < r.failures.size() && r.failures[f].index == k) ++f;
    else used.push_back(k);
  // Monte Carlo: equal weights over the successful samples (the rule's own when none failed).
  std::vector<double> w = r.plan.set.weights;
  if (monteCarlo && !r.failures.empty()) w.assign(used.size(), 1.0 / static_cast<double>(used.size()));
  const auto moments = [&](auto&& sampleValues, std::size_t n) {
    if (!r.momentsComputed) {  // NaN in every column the rule has
      const std::vector<double> nan(n, std::numeric_limits<double>::quiet_NaN()), none;
      return Moments{nan, nan, 0, r.plan.projection ? nan : none, monteCarlo ? nan : none, monteCarlo ? nan : none,
                     monteCarlo ? nan : none};
    }
    std::vector<const std::vector<double>*> values;
    for (std::size_t k : used) values.push_back(&sampleValues(r.records[k]));
    Moments m = weightedMoments(values, w);
    if (monteCarlo) addStandardErrors(m, values);
    if (r.plan.projection) addPceStd(m, values, *r.plan.projection);  // no sample failed: values are all
    return m;
  };
  if (!layout_.scalars.empty())
    r.scalarMoments = moments([](const SampleRecord& s) -> const std::vector<double>& { return s.scalars; },
                              layout_.scalars.size());
  for (std::size_t f = 0; f < layout_.fields.size(); ++f)
    r.fieldMoments.push_back(
        moments([f](const SampleRecord& s) -> const std::vector<double>& { return s.fields[f]; }, fieldSizes_[f]));
  if (!exact_ || !r.momentsComputed) return;
  // The exact moments do not depend on the sample: the first successful sample's copy serves.
  const auto field = [&](const std::string& name) -> const std::vector<double>& {
    return r.records[used.front()].fields[fieldIndex(layout_, name)];
  };
  const double h = gridSpacing(layout_);
  const std::size_t ux = fieldIndex(layout_, "ux"), uy = fieldIndex(layout_, "uy");
  r.errorMean = l2Error(r.fieldMoments[ux].mean, r.fieldMoments[uy].mean, field("exactMeanUx"), field("exactMeanUy"), h);
  r.errorStd = l2Error(r.fieldMoments[ux].std, r.fieldMoments[uy].std, field("exactStdUx"), field("exactStdUy"), h);
}

void compareWithLast(std::vector<LevelResult>& levels, const ResultLayout& layout) {
  if (levels.size() < 2) return;
  const std::size_t ux = fieldIndex(layout, "ux"), uy = fieldIndex(layout, "uy");
  const double h = gridSpacing(layout);
  const LevelResult& last = levels.back();
  if (!last.momentsComputed) return;
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    LevelResult& r = levels[k];
    if (!r.momentsComputed) continue;
    r.diffMean = l2Error(r.fieldMoments[ux].mean, r.fieldMoments[uy].mean, last.fieldMoments[ux].mean,
                         last.fieldMoments[uy].mean, h);
    r.diffStd = l2Error(r.fieldMoments[ux].std, r.fieldMoments[uy].std, last.fieldMoments[ux].std,
                        last.fieldMoments[uy].std, h);
  }
}

}  // namespace peristep::host
