#include "solvers/central_difference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/blocked_sum.hpp"
#include "core/errors.hpp"
#include "core/flush_denormals.hpp"
#include "core/timer.hpp"

namespace peristep {

CentralDifference::CentralDifference(DynamicProblem& problem, const IntegratorOptions& options)
    : problem_(problem) {
  require(std::isfinite(options.timeStep) && options.timeStep > 0,
          "centralDifference: the time step must be positive");
  stability_ = estimateStabilityLimit(problem_);
  dt_ = options.timeStep;
  if (dt_ > stability_.criticalStep) {
    if (!options.allowSubsteps) {
      std::ostringstream msg;
      msg << "centralDifference: time step " << dt_ << " s exceeds the stability limit "
          << stability_.criticalStep << " s (2/omega_max, omega_max = " << stability_.omegaMax
          << " rad/s); use a step below the limit or allow substeps";
      throw InvalidInput(msg.str());
    }
    const double substeps = std::ceil(dt_ / (0.95 * stability_.criticalStep));
    dt_ /= substeps;
  }
  const std::size_t n = problem_.dofs();
  u_ = problem_.initialDisplacement();
  v_ = problem_.initialVelocity();
  a_.assign(n, 0.0);
  f_.assign(n, 0.0);
  fNext_.assign(n, 0.0);
  volume_.resize(n);
  for (std::size_t d = 0; d < n; ++d) volume_[d] = problem_.model().pointVolume(d / 2);
  problem_.applyPrescribed(0.0, u_.data(), v_.data());
  problem_.acceleration(0.0, u_.data(), f_.data(), a_.data());
  ++stats_.rhsEvaluations;
}

void CentralDifference::step(double dt) {
  const std::size_t n = problem_.dofs();
  const char* fixed = problem_.prescribed().data();
  const double tNew = t_ + dt;
  // External work by the trapezoid rule on each displacement increment, consistent with the scheme:
  // the body force on free dofs (increment dt v^{k+1/2}), the reactions -V L on prescribed ones
  // (increment dt times their velocity, set by applyPrescribed).
  const double bMid = 0.5 * (problem_.bodyAmplitude(t_) + problem_.bodyAmplitude(tNew));
  const double* profile = problem_.bodyProfile().empty() ? nullptr : problem_.bodyProfile().data();
  double* u = u_.data();
  double* v = v_.data();
  double* a = a_.data();
  const double* V = volume_.data();
  // Fixed blocks, so the work is the same bits on any number of threads (core/blocked_sum.hpp).
  double work = blockedSum(n, [&](std::size_t d) {
    if (fixed[d]) return 0.0;
    v[d] += 0.5 * dt * a[d];
    u[d] += dt * v[d];
    return profile ? V[d] * bMid * profile[d] * dt * v[d] : 0.0;
  }, problem_.threaded());
  problem_.applyPrescribed(tNew, u, v);
  problem_.acceleration(tNew, u, fNext_.data(), a);
  const double* f0 = f_.data();
  const double* f1 = fNext_.data();
  work -= blockedSum(n, [&](std::size_t d) {
    if (!fixed[d]) {
      v[d] += 0.5 * dt * a[d];
      return 0.0;
    }
    return V[d] * 0.5 * (f0[d] + f1[d]) * v[d] * dt;  // v: the path's (scaled) velocity
  }, problem_.threaded());
  work_ += work;
  f_.swap(fNext_);
  t_ = tNew;
  ++stats_.steps;
  ++stats_.rhsEvaluations;
}

void CentralDifference::setState(double t, const double* u, const double* v, double work) {
  require(std::isfinite(t) && std::isfinite(work), "centralDifference: the state's time and work must be finite");
  std::copy(u, u + u_.size(), u_.begin());
  std::copy(v, v + v_.size(), v_.begin());
  t_ = t;
  work_ = work;
  // Recomputing the acceleration from u gives the same bits the uninterrupted run holds at t.
  problem_.applyPrescribed(t_, u_.data(), v_.data());
  problem_.acceleration(t_, u_.data(), f_.data(), a_.data());
  ++stats_.rhsEvaluations;
}

void CentralDifference::advanceTo(double t) {
  require(std::isfinite(t) && t >= t_ - 1e-12 * std::abs(t_), "centralDifference: cannot integrate backwards");
  const FlushDenormals flush;  // this thread; the threads of the force loop take their own
  const Stopwatch clock;
  // Whole steps, the last one landing exactly on t (shortened when t is not a multiple of the step:
  // the kick-drift-kick form allows a change of step).
  const double steps = std::ceil((t - t_) / dt_ - 1e-6);
  for (double k = 1; k < steps; ++k) step(dt_);
  if (steps >= 1) step(t - t_);
  for (std::size_t d = 0; d < u_.size(); ++d)
    if (!std::isfinite(u_[d]) || !std::isfinite(v_[d]))
      throw SolverFailure("centralDifference: the solution is no longer finite at t = " + std::to_string(t_) + " s");
  stats_.seconds += clock.seconds();
}

}  // namespace peristep
