#pragma once
// One small interface over the time integrators of the semi-discrete system, chosen by TimeIntegratorKind
// (solvers/time_integrator_kind.hpp, with their names):
//   centralDifference  explicit central difference 001:(35)-(36), fixed step, stability-checked
//   arkodeErk          SUNDIALS ARKODE ERKStep, explicit adaptive Runge-Kutta
//   cvodeBdf           SUNDIALS CVODE BDF (order <= 2 by default), Newton + matrix-free SPGMR with a
//                      preconditioner built from the rest-state tangent: for stiff problems
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "solvers/dynamic_problem.hpp"
#include "solvers/time_integrator_kind.hpp"

namespace peristep {

struct IntegratorOptions {
  double timeStep = 0;                 // central difference: the step [s]
  bool allowSubsteps = false;          // central difference: split a step above the stability limit
  double relativeTolerance = 1e-6;     // SUNDIALS: local error control
  double absoluteTolerance = 1e-12;    // SUNDIALS: on displacements [m]
  double velocityTolerance = 1e-6;     // SUNDIALS: absolute tolerance on velocities [m/s]
  long maxSteps = 100000000;           // SUNDIALS: per advanceTo call
  int maxOrder = 2;                    // cvodeBdf: BDF order cap (orders > 2 are not A-stable, and the
                                       // undamped modes of elastodynamics sit on the imaginary axis)
  int krylovDimension = 20;            // cvodeBdf: SPGMR restart length
};

struct IntegratorStats {
  long steps = 0;
  long rhsEvaluations = 0;             // force evaluations L(u)
  long jacobianProducts = 0;           // directional derivatives of L (about one force evaluation each)
  long linearIterations = 0, nonlinearIterations = 0, preconditionerSetups = 0, errorTestFailures = 0;
  double seconds = 0;                  // wall time spent in advanceTo
  long forceEquivalents() const { return rhsEvaluations + jacobianProducts; }
  IntegratorStats& operator+=(const IntegratorStats& o) {
    steps += o.steps;
    rhsEvaluations += o.rhsEvaluations;
    jacobianProducts += o.jacobianProducts;
    linearIterations += o.linearIterations;
    nonlinearIterations += o.nonlinearIterations;
    preconditionerSetups += o.preconditionerSetups;
    errorTestFailures += o.errorTestFailures;
    seconds += o.seconds;
    return *this;
  }
  friend IntegratorStats operator+(IntegratorStats a, const IntegratorStats& b) { return a += b; }
};

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;
  virtual std::string_view name() const = 0;
  // Integrate up to time t (>= time()); throws SolverFailure on a failed step and InvalidInput on
  // a request the method refuses (a step above the stability limit).
  virtual void advanceTo(double t) = 0;
  virtual double time() const = 0;
  virtual const double* displacement() const = 0;  // 2 N values at time()
  virtual const double* velocity() const = 0;
  // Work done on the body since t = 0 by the body force and by the reactions of the prescribed dofs.
  virtual double externalWork() const = 0;
  virtual IntegratorStats stats() const = 0;
  // Continue from (u, v) at time t with `work` done so far (a checkpoint, or new loads after
  // DynamicProblem::rescaleLoads); prescribed dofs take their path's values at t. The adaptive
  // SUNDIALS integrators restart there with a fresh step-size history (and BDF at order 1), so their
  // continuation agrees with an uninterrupted run to the tolerances, not bit for bit; central
  // difference continues exactly. Statistics keep counting.
  virtual void setState(double t, const double* u, const double* v, double work) = 0;
};

// Throws InvalidInput for invalid options (a step above the stability limit).
std::unique_ptr<TimeIntegrator> makeTimeIntegrator(TimeIntegratorKind kind, DynamicProblem& problem,
                                                   const IntegratorOptions& options);
std::unique_ptr<TimeIntegrator> makeTimeIntegrator(std::string_view name, DynamicProblem& problem,
                                                   const IntegratorOptions& options);

}  // namespace peristep
