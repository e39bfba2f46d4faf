#include "models/lps_discretization.hpp"

#include <deque>
#include <mutex>
#include <utility>

#include "core/timer.hpp"
#include "quadrature/optimization_weights.hpp"

namespace peristep {

LpsDiscretization LpsDiscretization::build(const GridSpec& spec) {
  LpsDiscretization d;
  d.cloud = makeRectangle(spec);
  Stopwatch clock;
  d.neighbours = findNeighbours(d.cloud, d.cloud.delta);
  d.dofs = numberDofs(d.cloud, d.neighbours);
  d.neighbourSeconds = clock.lap();
  // Weights only where a dilatation is computed: the points carrying a theta unknown.
  d.weights = optimizationWeights(d.cloud, d.neighbours, d.dofs.thetaPoints());
  d.weightSeconds = clock.lap();
  return d;
}

std::shared_ptr<const LpsDiscretization> sharedDiscretization(const GridSpec& spec) {
  static std::mutex mutex;
  static std::deque<std::pair<GridSpec, std::shared_ptr<const LpsDiscretization>>> recent;
  constexpr std::size_t kKept = 2;
  std::lock_guard lock(mutex);
  for (auto it = recent.begin(); it != recent.end(); ++it)
    if (it->first.sameCloud(spec)) {
      auto entry = *it;
      recent.erase(it);
      recent.push_front(entry);
      return entry.second;
    }
  auto built = std::make_shared<const LpsDiscretization>(LpsDiscretization::build(spec));
  recent.emplace_front(spec, built);
  if (recent.size() > kKept) recent.pop_back();
  return built;
}

}  // namespace peristep
