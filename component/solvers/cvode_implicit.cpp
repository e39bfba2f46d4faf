#include "solvers/cvode_implicit.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/timer.hpp"
#include "solvers/sundials_support.hpp"
#include "solvers/tangent_preconditioner.hpp"

namespace peristep {
namespace {

class CvodeImplicit final : public TimeIntegrator {
 public:
  CvodeImplicit(DynamicProblem& problem, const IntegratorOptions& o)
      : problem_(problem),
        n_(problem.dofs()),
        y_(static_cast<sunindextype>(2 * n_ + 1), ctx_),
        atol_(static_cast<sunindextype>(2 * n_ + 1), ctx_),
        f_(n_),
        precond_(problem) {
    require(o.relativeTolerance > 0 && o.absoluteTolerance > 0 && o.velocityTolerance > 0,
            "cvodeBdf: tolerances must be positive");
    require(o.maxOrder >= 1 && o.maxOrder <= 5, "cvodeBdf: maxOrder must lie in 1..5");
    require(o.krylovDimension >= 1, "cvodeBdf: krylovDimension must be positive");
    sundials::initialState(problem_, y_.data());
    sundials::absoluteTolerances(n_, o.absoluteTolerance, o.velocityTolerance, atol_.data());
    mem_.reset(CVodeCreate(CV_BDF, ctx_));
    if (!mem_) throw SolverFailure("cvodeBdf: CVodeCreate failed");
    void* m = mem_.get();
    check(CVodeSetErrHandlerFn(m, &sundials::keepMessage, &message_), "CVodeSetErrHandlerFn");
    check(CVodeInit(m, &CvodeImplicit::rhs, 0.0, y_), "CVodeInit");
    check(CVodeSetUserData(m, this), "CVodeSetUserData");
    check(CVodeSVtolerances(m, o.relativeTolerance, atol_), "CVodeSVtolerances");
    check(CVodeSetMaxOrd(m, o.maxOrder), "CVodeSetMaxOrd");
    check(CVodeSetMaxNumSteps(m, o.maxSteps), "CVodeSetMaxNumSteps");
    ls_.reset(SUNLinSol_SPGMR(y_, SUN_PREC_LEFT, o.krylovDimension, ctx_));
    if (!ls_) throw SolverFailure("cvodeBdf: SUNLinSol_SPGMR failed");
    check(CVodeSetLinearSolver(m, ls_.get(), nullptr), "CVodeSetLinearSolver");
    check(CVodeSetJacTimes(m, nullptr, &CvodeImplicit::jtimes), "CVodeSetJacTimes");
    check(CVodeSetPreconditioner(m, &CvodeImplicit::psetup, &CvodeImplicit::psolve), "CVodeSetPreconditioner");
  }

  std::string_view name() const override { return "cvodeBdf"; }
  double time() const override { return t_; }
  const double* displacement() const override { return y_.data(); }
  const double* velocity() const override { return y_.data() + n_; }
  double externalWork() const override { return y_.data()[2 * n_]; }

  void advanceTo(double t) override {
    require(std::isfinite(t) && t >= t_, "cvodeBdf: cannot integrate backwards");
    if (t == t_) return;
    const Stopwatch clock;
    check(CVodeSetStopTime(mem_.get(), t), "CVodeSetStopTime");
    double reached = t_;
    const int flag = CVode(mem_.get(), t, y_, &reached, CV_NORMAL);
    seconds_ += clock.seconds();
    if (!callbackError_.empty()) throw SolverFailure("cvodeBdf: " + callbackError_);
    if (flag < 0) throw SolverFailure("cvodeBdf: step failed at t = " + std::to_string(reached) + " s: " + message_);
    t_ = reached;
  }

  IntegratorStats stats() const override { return counters() + carried_; }

  void setState(double t, const double* u, const double* v, double work) override {
    sundials::restartState(problem_, t, u, v, work, y_.data());
    const IntegratorStats before = counters();
    check(CVodeReInit(mem_.get(), t, y_), "CVodeReInit");
    sundials::carryCounters(before, counters(), carried_);
    t_ = t;
  }

 private:
  IntegratorStats counters() const {
    IntegratorStats s;
    void* m = mem_.get();
    CVodeGetNumSteps(m, &s.steps);
    CVodeGetNumRhsEvals(m, &s.rhsEvaluations);
    CVodeGetNumJtimesEvals(m, &s.jacobianProducts);
    CVodeGetNumLinIters(m, &s.linearIterations);
    CVodeGetNumNonlinSolvIters(m, &s.nonlinearIterations);
    CVodeGetNumErrTestFails(m, &s.errorTestFailures);
    s.preconditionerSetups = precond_.factorizations();
    s.seconds = seconds_;
    return s;
  }
  template <class Body>
  static int guarded(void* data, Body&& body) {
    auto* self = static_cast<CvodeImplicit*>(data);
    try {
      return body(*self);
    } catch (const std::exception& e) {
      self->callbackError_ = e.what();
      return -1;
    }
  }
  static int rhs(double t, N_Vector y, N_Vector ydot, void* data) {
    return guarded(data, [&](CvodeImplicit& s) {
      return sundials::evaluateRhs(s.problem_, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s.f_.data()) ? 0 : 1;
    });
  }
  // J v with J = d(u', v', W')/d(u, v, W); the W row (external power) is left out: W feeds nothing back.
  static int jtimes(N_Vector v, N_Vector Jv, double, N_Vector y, N_Vector, void* data, N_Vector) {
    return guarded(data, [&](CvodeImplicit& s) {
      const std::size_t n = s.n_;
      const double* vv = N_VGetArrayPointer(v);
      const double* yy = N_VGetArrayPointer(y);
      double* out = N_VGetArrayPointer(Jv);
      for (std::size_t d = 0; d < n; ++d) out[d] = vv[n + d];
      s.problem_.accelerationDerivative(yy, vv, out + n);
      out[2 * n] = 0.0;
      return 0;
    });
  }
  static int psetup(double, N_Vector, N_Vector, int, int* jcur, double gamma, void* data) {
    return guarded(data, [&](CvodeImplicit& s) {
      s.precond_.setup(gamma);
      *jcur = 0;  // the rest-state tangent is never re-evaluated
      return 0;
    });
  }
  static int psolve(double, N_Vector, N_Vector, N_Vector r, N_Vector z, double gamma, double, int, void* data) {
    return guarded(data, [&](CvodeImplicit& s) {
      const double* rr = N_VGetArrayPointer(r);
      double* zz = N_VGetArrayPointer(z);
      s.precond_.solve(rr, zz, gamma);
      zz[2 * s.n_] = rr[2 * s.n_];
      return 0;
    });
  }
  void check(int flag, const char* what) const {
    if (flag < 0) throw SolverFailure(std::string("cvodeBdf: ") + what + " failed: " + message_);
  }

  DynamicProblem& problem_;
  std::size_t n_;
  sundials::Context ctx_;
  sundials::Vector y_, atol_;
  std::vector<double> f_;
  TangentPreconditioner precond_;
  std::string message_, callbackError_;  // before the SUNDIALS memory, which reports into message_
  struct FreeMem {
    void operator()(void* m) const { CVodeFree(&m); }
  };
  struct FreeLs {
    void operator()(SUNLinearSolver ls) const { SUNLinSolFree(ls); }
  };
  std::unique_ptr<_generic_SUNLinearSolver, FreeLs> ls_;
  std::unique_ptr<void, FreeMem> mem_;
  double t_ = 0, seconds_ = 0;
  IntegratorStats carried_;  // counts from before a ReInit
};

}  // namespace

std::unique_ptr<TimeIntegrator> makeCvodeImplicit(DynamicProblem& problem, const IntegratorOptions& options) {
  return std::make_unique<CvodeImplicit>(problem, options);
}

}  // namespace peristep
