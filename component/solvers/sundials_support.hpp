#pragma once
// Small RAII wrappers over the SUNDIALS 6 C objects, and the state layout shared by the SUNDIALS
// integrators: y = [u (2N) | v (2N) | W], W the external work (a diagnostic, excluded from error control).
#include <string>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include "core/errors.hpp"
#include "solvers/dynamic_problem.hpp"
#include "solvers/time_integrator.hpp"

namespace peristep::sundials {

class Context {
 public:
  Context() {
    if (SUNContext_Create(nullptr, &ctx_) != 0) throw SolverFailure("SUNDIALS: could not create a context");
  }
  ~Context() { SUNContext_Free(&ctx_); }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  operator SUNContext() const { return ctx_; }

 private:
  SUNContext ctx_ = nullptr;
};

class Vector {
 public:
  Vector(sunindextype n, SUNContext ctx) : v_(N_VNew_Serial(n, ctx)) {
    if (!v_) throw SolverFailure("SUNDIALS: could not allocate a vector of length " + std::to_string(n));
  }
  ~Vector() { N_VDestroy(v_); }
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
  operator N_Vector() const { return v_; }
  double* data() const { return N_VGetArrayPointer(v_); }

 private:
  N_Vector v_;
};

// Error handler for CVODE and ARKODE: keeps the last message for the exception instead of printing.
inline void keepMessage(int, const char* module, const char* function, char* msg, void* data) {
  *static_cast<std::string*>(data) = std::string(module ? module : "") + "::" + (function ? function : "") + ": " +
                                     (msg ? msg : "");
}

// Fill y with the problem's initial state, and the absolute tolerances (W uncontrolled).
void initialState(DynamicProblem& problem, double* y);
// Fill y with (u, v, work) at time t, the prescribed dofs on their path (a restart).
void restartState(const DynamicProblem& problem, double t, const double* u, const double* v, double work, double* y);
// Counters that a ReInit may reset: after - before is added to carried so that totals keep counting.
void carryCounters(const IntegratorStats& before, const IntegratorStats& after, IntegratorStats& carried);
void absoluteTolerances(std::size_t dofs, double displacementTolerance, double velocityTolerance, double* tol);
// ydot = [v, a(t, u), P(t, u, v)]; f is scratch of 2N values. Returns false when the result is not finite.
bool evaluateRhs(DynamicProblem& problem, double t, const double* y, double* ydot, double* f);

}  // namespace peristep::sundials
