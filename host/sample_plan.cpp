#include "sample_plan.hpp"

#include <sstream>
#include <stdexcept>

#include "host_errors.hpp"
#include "result_layout.hpp"
#include "sampling/monte_carlo.hpp"
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

}  // namespace

LevelPlan planLevel(const SamplingOptions& options, const RandomSpace& space, std::uint64_t level) {
  const bool random = !space.laws.empty();
  if (!random && options.rule != SampleRule::MonteCarlo)
    throw InputError("the scene has no random coordinates (xiDistribution): only --rule mc, which varies the seed, "
                     "applies");
  LevelPlan plan;
  try {
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
