#pragma once
// Convergence-rate estimate of 001 Sec. 6.1.2 for displacement fields on nested lattices of square cells.
#include "scenes/dynamic_scene.hpp"

namespace peristep {

// || u_coarse - u_fine ||_{L2(D)} of the piecewise-constant extensions 001:(26): every cell of the
// fine lattice lies in exactly one cell of the coarse one (fine h = coarse h / integer).
double nestedL2Difference(const DynamicScene& coarse, const double* uCoarse, const DynamicScene& fine,
                          const double* uFine);

// 001:(106): b = (log ||u1 - u2|| - log ||u2 - u3||)/log r for mesh ratio r = h1/h2 = h2/h3.
double rateEstimate(double d12, double d23, double ratio);

}  // namespace peristep
