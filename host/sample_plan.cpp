#include "sample_plan.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "host_errors.hpp"
#include "result_layout.hpp"
#include "sampling/monte_carlo.hpp"
#include "sampling/nested_rules.hpp"
#include "sampling/tensor_grid.hpp"
#include "simulation.hpp"

namespace peristep::host {

namespace {

constexpr std::int64_t kNormal = 0, kUniform = 1;  // PERISTEP_XI_NORMAL, PERISTEP_XI_UNIFORM; 2: unused

const Variable& variable(const ModelDescription& md, const std::string& name) {
  const Variable* v = md.find(name);
  if (!v) throw InputError(md.modelName + " has no variable " + name + ", which a sample study needs");
  return *v;
}

// Exact text of a value (hexadecimal floating point): two samples share a file only if identical.
std::string exactText(const Values& values) {
  std::ostringstream out;
  out << std::hexfloat;
  std::visit([&](const auto& vec) { for (const auto& e : vec) out << e << ','; }, values);
  return out.str();
}

void replace(Scene& scene, const Variable& v, Values values) {
  for (Setting& s : scene.parameters)
    if (s.variable.name == v.name) {
      s.values = std::move(values);
      return;
    }
  scene.parameters.push_back({v, std::move(values)});
}

}  // namespace

RandomSpace readRandomSpace(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
                            const FmuInstance::Options& options) {
  FmuInstance probe(library, md, options);
  setSceneParameters(probe, scene);
  probe.enterInitializationMode(scene.loading.startTime, scene.loading.stopTime);
  const Variable& law = variable(md, "xiDistribution");
  RandomSpace space;
  space.nModes = static_cast<std::size_t>(elementCount(probe.shape(law)));
  const auto codes = std::get<std::vector<std::int64_t>>(probe.get(law, space.nModes));
  for (std::size_t k = 0; k < codes.size(); ++k) {
    if (codes[k] != kNormal && codes[k] != kUniform) continue;
    space.index.push_back(k);
    space.laws.push_back(codes[k] == kNormal ? sampling::Law::Normal : sampling::Law::Uniform);
  }
  return space;
}

namespace {

sampling::SampleSet pointsOf(const SamplingOptions& options, const RandomSpace& space, std::uint64_t level) {
  const int l = static_cast<int>(level);
  switch (options.rule) {
    case SampleRule::Tensor:
      if (level < 1) throw InputError("--rule tensor: the level is the number of points per coordinate, >= 1");
      return sampling::tensorGrid(space.laws, l);
    case SampleRule::Smolyak:
      return sampling::smolyakGrid(space.laws, l, options.nested ? sampling::Family::Nested : sampling::Family::Gauss);
    case SampleRule::MonteCarlo:
      if (level < 1) throw InputError("--rule mc: the number of samples must be >= 1");
      if (!space.laws.empty()) return sampling::monteCarlo(space.laws, level, options.seed);
      sampling::SampleSet seeds;  // no coordinates: equal weights, the seed varies
      seeds.weights.assign(level, 1.0 / static_cast<double>(level));
      return seeds;
  }
  return {};
}

// How many samples the plan holds, counted before anything is built (a Smolyak grid of a high level in
// many coordinates has more points than memory holds): tensor n^N; Monte Carlo the count asked for;
// Smolyak the points of the combination technique's tensor grids before coincident ones merge, counted
// up to level 200 (beyond it a grid in two or more coordinates has millions of points: the count at
// level 200 is a lower bound that already refuses it).
double plannedSamples(const SamplingOptions& options, const RandomSpace& space, std::uint64_t level) {
  const std::size_t N = space.laws.size();
  switch (options.rule) {
    case SampleRule::Tensor: return std::pow(static_cast<double>(level), static_cast<double>(N));
    case SampleRule::MonteCarlo: return static_cast<double>(level);
    case SampleRule::Smolyak: break;
  }
  const auto points = [&](sampling::Law law, std::uint64_t l) {  // of the 1D rule at level l
    if (!options.nested) return 2.0 * static_cast<double>(l) + 1;
    if (l > static_cast<std::uint64_t>(sampling::nestedMaxLevel(law)))
      throw std::invalid_argument("the nested rules have levels up to " + std::to_string(sampling::nestedMaxLevel(law)));
    return static_cast<double>(sampling::sparseGridRule(law, static_cast<int>(l), sampling::Family::Nested).nodes.size());
  };
  if (N == 1) return points(space.laws[0], level);
  const std::size_t L = static_cast<std::size_t>(std::min<std::uint64_t>(level, 200));
  // count[s]: points of all tensor grids whose 1D levels sum to s, over the coordinates so far.
  std::vector<double> count(L + 1, 0.0);
  count[0] = 1;
  for (sampling::Law law : space.laws) {
    std::vector<double> next(L + 1, 0.0);
    for (std::size_t s = 0; s <= L; ++s)
      for (std::size_t l = 0; l <= s; ++l) next[s] += count[s - l] * points(law, l);
    count = std::move(next);
  }
  double total = 0;  // the combination technique keeps the sums L - N + 1 .. L
  for (std::size_t s = 0; s <= L; ++s)
    if (s + N >= L + 1) total += count[s];
  return total;
}

}  // namespace

std::string ruleName(SampleRule rule) {
  switch (rule) {
    case SampleRule::Tensor: return "tensor";
    case SampleRule::Smolyak: return "smolyak";
    case SampleRule::MonteCarlo: return "mc";
  }
  return "?";
}

LevelPlan planLevel(const SamplingOptions& options, const RandomSpace& space, std::uint64_t level) {
  const bool random = !space.laws.empty();
  if (!random && options.rule != SampleRule::MonteCarlo)
    throw InputError("the scene has no random coordinates (xiDistribution): only --rule mc, which varies the seed, "
                     "applies");
  LevelPlan plan;
  try {
    if (const double planned = plannedSamples(options, space, level); planned > kMaxPlannedSamples) {
      std::ostringstream why;
      why.precision(3);
      why << "--rule " << ruleName(options.rule) << " at level " << level << " in " << space.laws.size()
          << " random coordinate(s) plans about " << planned << " samples, more than the " << kMaxPlannedSamples
          << " a study may hold; choose a lower level"
          << (options.rule == SampleRule::Smolyak ? " (level 1 has 2N + 1 points, level 2 about 2N^2)" : "");
      throw InputError(why.str());
    }
    plan.set = pointsOf(options, space, level);
    if (options.rule == SampleRule::Smolyak)
      plan.projection = sampling::sparsePseudoSpectral(
          space.laws, static_cast<int>(level), options.nested ? sampling::Family::Nested : sampling::Family::Gauss);
  } catch (const std::logic_error& e) {  // the rules refuse a level they do not have, or a grid too large
    throw InputError("level " + std::to_string(level) + ": " + e.what());
  }
  for (std::size_t k = 0; k < plan.set.size(); ++k) {
    SampleJob job;
    job.xi.assign(space.nModes, 0.0);
    const auto point = plan.set.point(k);
    for (std::size_t d = 0; d < space.index.size(); ++d) job.xi[space.index[d]] = point[d];
    if (!random) job.seed = options.seed + k;  // sample k is the microstructure of seed + k
    plan.jobs.push_back(std::move(job));
  }
  return plan;
}

Scene sceneForSample(const Scene& scene, const ModelDescription& md, const SampleJob& job, std::string& definition) {
  Scene s = scene;
  if (!job.xi.empty()) replace(s, variable(md, "xi"), job.xi);
  if (job.seed) replace(s, variable(md, "seed"), std::vector<std::uint64_t>{*job.seed});
  std::ostringstream text;
  text << md.instantiationToken << '|';
  for (const Setting& p : s.parameters) text << p.variable.name << '=' << exactText(p.values) << '|';
  const Loading& l = s.loading;
  text << std::hexfloat << "loading:" << (l.input ? l.input->name : std::string("-")) << ',' << l.from << ',' << l.to
       << ',' << l.steps << ',' << l.startTime << ',' << l.stopTime;
  definition = text.str();
  return s;
}

}  // namespace peristep::host
