#include "solvers/arkode_explicit.hpp"

#include <arkode/arkode_erkstep.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/timer.hpp"
#include "solvers/sundials_support.hpp"

namespace peristep {
namespace {

class ArkodeExplicit final : public TimeIntegrator {
 public:
  ArkodeExplicit(DynamicProblem& problem, const IntegratorOptions& o)
      : problem_(problem),
        n_(problem.dofs()),
        y_(static_cast<sunindextype>(2 * n_ + 1), ctx_),
        atol_(static_cast<sunindextype>(2 * n_ + 1), ctx_),
        f_(n_) {
    require(o.relativeTolerance > 0 && o.absoluteTolerance > 0 && o.velocityTolerance > 0,
            "arkodeErk: tolerances must be positive");
    sundials::initialState(problem_, y_.data());
    sundials::absoluteTolerances(n_, o.absoluteTolerance, o.velocityTolerance, atol_.data());
    mem_.reset(ERKStepCreate(&ArkodeExplicit::rhs, 0.0, y_, ctx_));
    if (!mem_) throw SolverFailure("arkodeErk: ERKStepCreate failed");
    check(ERKStepSetUserData(mem_.get(), this), "ERKStepSetUserData");
    check(ERKStepSetErrHandlerFn(mem_.get(), &sundials::keepMessage, &message_), "ERKStepSetErrHandlerFn");
    check(ERKStepSVtolerances(mem_.get(), o.relativeTolerance, atol_), "ERKStepSVtolerances");
    check(ERKStepSetMaxNumSteps(mem_.get(), o.maxSteps), "ERKStepSetMaxNumSteps");
  }
  std::string_view name() const override { return "arkodeErk"; }
  double time() const override { return t_; }
  const double* displacement() const override { return y_.data(); }
  const double* velocity() const override { return y_.data() + n_; }
  double externalWork() const override { return y_.data()[2 * n_]; }

  void advanceTo(double t) override {
    require(std::isfinite(t) && t >= t_, "arkodeErk: cannot integrate backwards");
    if (t == t_) return;
    const Stopwatch clock;
    check(ERKStepSetStopTime(mem_.get(), t), "ERKStepSetStopTime");
    double reached = t_;
    const int flag = ERKStepEvolve(mem_.get(), t, y_, &reached, ARK_NORMAL);
    seconds_ += clock.seconds();
    if (!callbackError_.empty()) throw SolverFailure("arkodeErk: " + callbackError_);
    if (flag < 0) throw SolverFailure("arkodeErk: step failed at t = " + std::to_string(reached) + " s: " + message_);
    t_ = reached;
  }

  IntegratorStats stats() const override { return counters() + carried_; }

  void setState(double t, const double* u, const double* v, double work) override {
    sundials::restartState(problem_, t, u, v, work, y_.data());
    const IntegratorStats before = counters();
    check(ERKStepReInit(mem_.get(), &ArkodeExplicit::rhs, t, y_), "ERKStepReInit");
    sundials::carryCounters(before, counters(), carried_);
    t_ = t;
  }

 private:
  static int rhs(double t, N_Vector y, N_Vector ydot, void* data) {
    auto* self = static_cast<ArkodeExplicit*>(data);
    try {
      // Non-finite forces: ask for a smaller step (recoverable) rather than abort.
      return sundials::evaluateRhs(self->problem_, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot),
                                   self->f_.data())
                 ? 0
                 : 1;
    } catch (const std::exception& e) {
      self->callbackError_ = e.what();
      return -1;
    }
  }
  IntegratorStats counters() const {
    IntegratorStats s;
    ERKStepGetNumSteps(mem_.get(), &s.steps);
    ERKStepGetNumRhsEvals(mem_.get(), &s.rhsEvaluations);
    ERKStepGetNumErrTestFails(mem_.get(), &s.errorTestFailures);
    s.seconds = seconds_;
    return s;
  }
  void check(int flag, const char* what) const {
    if (flag < 0) throw SolverFailure(std::string("arkodeErk: ") + what + " failed: " + message_);
  }

  DynamicProblem& problem_;
  std::size_t n_;
  sundials::Context ctx_;
  sundials::Vector y_, atol_;
  std::vector<double> f_;
  std::string message_, callbackError_;  // before the SUNDIALS memory, which reports into message_
  struct Free {
    void operator()(void* m) const { ERKStepFree(&m); }
  };
  std::unique_ptr<void, Free> mem_;
  double t_ = 0, seconds_ = 0;
  IntegratorStats carried_;  // counts from before a ReInit
};

}  // namespace

std::unique_ptr<TimeIntegrator> makeArkodeExplicit(DynamicProblem& problem, const IntegratorOptions& options) {
  return std::make_unique<ArkodeExplicit>(problem, options);
}

}  // namespace peristep
