#include "learning/data_sets.hpp"

#include <cmath>

namespace peristep::learning {

StaticData staticData(const CoarseDataSet& set) {
  StaticData d{PeriodicLattice{set.grid.nx, set.grid.ny, set.grid.hx, set.grid.hy}, {}, {}, 0.0};
  double rho = 0;
  std::size_t count = 0;
  for (const CoarseFields& f : set.samples) {
    d.samples.push_back({f.u, f.b});
    double bb = 0;
    for (double b : f.b) bb += b * b;
    d.weight.push_back(1.0 / std::sqrt(bb / static_cast<double>(f.b.size())));  // relative residual per sample
    for (double r : f.rho) rho += r, ++count;
  }
  d.rho = rho / static_cast<double>(count);
  return d;
}

FractureFrames fractureFrames(const CoarseDataSet& set) {
  FractureFrames frames{set.grid, set.frameInterval / kTimeUnit, set.samples.front().rho, {}, {}};
  for (const CoarseFields& f : set.samples) frames.u.push_back(f.u), frames.b.push_back(f.b);
  return frames;
}

}  // namespace peristep::learning
