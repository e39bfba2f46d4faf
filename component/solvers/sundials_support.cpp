#include "solvers/sundials_support.hpp"

#include <algorithm>
#include <cmath>

namespace peristep::sundials {

void initialState(DynamicProblem& problem, double* y) {
  const std::size_t n = problem.dofs();
  for (std::size_t d = 0; d < n; ++d) {
    y[d] = problem.initialDisplacement()[d];
    y[n + d] = problem.initialVelocity()[d];
  }
  y[2 * n] = 0.0;
}

void restartState(const DynamicProblem& problem, double t, const double* u, const double* v, double work, double* y) {
  require(std::isfinite(t) && std::isfinite(work), "restart: the state's time and work must be finite");
  const std::size_t n = problem.dofs();
  std::copy(u, u + n, y);
  std::copy(v, v + n, y + n);
  problem.applyPrescribed(t, y, y + n);
  y[2 * n] = work;
}

void carryCounters(const IntegratorStats& before, const IntegratorStats& after, IntegratorStats& carried) {
  // Whether or not this SUNDIALS version zeroes a counter on ReInit, totals stay monotone.
  carried.steps += before.steps - after.steps;
  carried.rhsEvaluations += before.rhsEvaluations - after.rhsEvaluations;
  carried.jacobianProducts += before.jacobianProducts - after.jacobianProducts;
  carried.linearIterations += before.linearIterations - after.linearIterations;
  carried.nonlinearIterations += before.nonlinearIterations - after.nonlinearIterations;
  carried.errorTestFailures += before.errorTestFailures - after.errorTestFailures;
}

void absoluteTolerances(std::size_t n, double displacementTolerance, double velocityTolerance, double* tol) {
  for (std::size_t d = 0; d < n; ++d) {
    tol[d] = displacementTolerance;
    tol[n + d] = velocityTolerance;
  }
  tol[2 * n] = 1e300;  // the work W only records; it must not drive the step size
}

bool evaluateRhs(DynamicProblem& problem, double t, const double* y, double* ydot, double* f) {
  const std::size_t n = problem.dofs();
  const double* u = y;
  const double* v = y + n;
  problem.acceleration(t, u, f, ydot + n);
  bool finite = true;
  for (std::size_t d = 0; d < n; ++d) {
    ydot[d] = v[d];  // prescribed dofs keep v = their constant velocity since their a = 0
    finite = finite && std::isfinite(ydot[n + d]);
  }
  ydot[2 * n] = problem.externalPower(t, f, v);
  return finite && std::isfinite(ydot[2 * n]);
}

}  // namespace peristep::sundials
