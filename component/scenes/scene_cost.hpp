#pragma once
// What a scene set-up will cost, estimated from its parameters alone before anything is allocated, so
// that a request beyond the limits is refused at once with the estimate (instead of exhausting memory
// or running for hours). The models are fitted to measurements (docs/performance.md and the commit that
// added this file) and are meant to be right within a factor of about 3, not exact.
#include <string>

#include "scenes/scene_model.hpp"

namespace peristep {

struct CostEstimate {
  double bytes = 0;    // peak memory of the set-up
  double seconds = 0;  // run time of the set-up on one 2-core machine of today
  // The parts that dominate memory and time, for the message ("the factorization of about 7.1e+03 unknowns ...").
  std::string mostMemory, mostTime;
};

CostEstimate estimateSetUp(const SceneParameters& p);

// Throws InvalidInput naming the estimate, the limit and what to change when the set-up of p exceeds
// p.limits (a zero limit is no limit).
void checkSetUpLimits(const SceneParameters& p);

}  // namespace peristep
