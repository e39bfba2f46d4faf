#include "models/lps_discretization.hpp"

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

}  // namespace peristep
