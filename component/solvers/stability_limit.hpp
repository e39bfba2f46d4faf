#pragma once
// Stability limit of the explicit central difference scheme for the semi-discrete system.
#include "solvers/dynamic_problem.hpp"

namespace peristep {

struct StabilityEstimate {
  double omegaMax = 0;      // estimate of the largest angular frequency [rad/s]
  double criticalStep = 0;  // 2/omegaMax: central difference is stable for dt below it
  int iterations = 0;
};

// Central difference applied to u'' = A u is stable iff dt <= 2/sqrt(lambda_max(-A)). A is the
// tangent of the acceleration at rest, restricted to the free dofs. For the potentials of 001 Sec. 6,
// f'' and g'' are largest at zero strain, so the rest-state tangent bounds the tangent of every
// deformed state in the Loewner order and the limit holds for the whole (nonlinear) run.
// lambda_max is estimated by Lanczos (matrix free) plus the residual bound of its Ritz pair, which
// errs on the safe (large) side in practice.
StabilityEstimate estimateStabilityLimit(DynamicProblem& problem, int maxIterations = 80);

}  // namespace peristep
