#include "sample_study.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

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

void SampleStudy::describe(const Scene& scene) {
  pending_ = std::make_unique<Simulation>(library_, md_, scene, options_);
  layout_ = pending_->layout();
  for (const ArrayInfo& f : layout_.fields) fieldSizes_.push_back(elementCount(f.shape));
  exact_ = md_.find("hasExactMoments") && pending_->readInteger("hasExactMoments") == 1;
  described_ = true;
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

LevelResult SampleStudy::runLevel(const SamplingOptions& rule, const RandomSpace& space, std::uint64_t level,
                                  const std::function<void(std::size_t, std::size_t)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  LevelResult r;
  r.level = level;
  r.plan = planLevel(rule, space, level);
  for (const SampleJob& job : r.plan.jobs) {
    std::string definition;
    const Scene scene = sceneForSample(scene_, md_, job, definition);
    const std::uint64_t key = SampleStore::key(componentId_ + '|' + definition);
    if (!described_) {
      describe(scene);
      pendingDefinition_ = definition;
    }
    std::optional<SampleRecord> record = store_.load(key, layout_.scalars.size(), fieldSizes_);
    if (record) {
      ++r.reused;
    } else {
      if (pending_ && pendingDefinition_ != definition) pending_.reset();
      try {
        record = runSample(scene);
      } catch (const RunError& e) {
        std::string xi;
        char buf[32];
        for (double v : job.xi) {
          std::snprintf(buf, sizeof buf, "%.6g", v + 0.0);  // + 0.0: no "-0" for the nodes on an axis
          xi += (xi.empty() ? "" : ", ") + std::string(buf);
        }
        throw RunError("sample " + std::to_string(r.records.size() + 1) + " of " + std::to_string(r.plan.jobs.size()) +
                       " (xi = [" + xi + "]" + (job.seed ? ", seed " + std::to_string(*job.seed) : "") + "): " +
                       e.what() + "; finished samples are kept in " + store_.directory().string());
      }
      store_.save(key, *record);
      ++r.computed;
    }
    r.records.push_back(std::move(*record));
    if (progress) progress(r.records.size(), r.plan.jobs.size());
  }
  pending_.reset();
  finish(r);
  r.seconds = secondsSince(start);
  return r;
}

void SampleStudy::finish(LevelResult& r) const {
  const std::vector<double>& w = r.plan.set.weights;
  std::vector<const std::vector<double>*> values;
  for (const SampleRecord& s : r.records) values.push_back(&s.scalars);
  if (!layout_.scalars.empty()) r.scalarMoments = weightedMoments(values, w);
  for (std::size_t f = 0; f < layout_.fields.size(); ++f) {
    values.clear();
    for (const SampleRecord& s : r.records) values.push_back(&s.fields[f]);
    r.fieldMoments.push_back(weightedMoments(values, w));
  }
  if (!exact_) return;
  // The exact moments do not depend on the sample: the first sample's copy serves.
  const auto field = [&](const std::string& name) -> const std::vector<double>& {
    return r.records.front().fields[fieldIndex(layout_, name)];
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
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    LevelResult& r = levels[k];
    r.diffMean = l2Error(r.fieldMoments[ux].mean, r.fieldMoments[uy].mean, last.fieldMoments[ux].mean,
                         last.fieldMoments[uy].mean, h);
    r.diffStd = l2Error(r.fieldMoments[ux].std, r.fieldMoments[uy].std, last.fieldMoments[ux].std,
                        last.fieldMoments[uy].std, h);
  }
}

}  // namespace peristep::host
