#include "solvers/central_difference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/timer.hpp"

namespace peristep {

CentralDifference::CentralDifference(DynamicProblem& problem, const IntegratorOptions& options)
    : problem_(problem) {
  require(std::isfinite(options.timeStep) && options.timeStep > 0,
          "central_difference: the time step must be positive");
  stability_ = estimateStabilityLimit(problem_);
  dt_ = options.timeStep;
  if (dt_ > stability_.criticalStep) {
    if (!options.allowSubsteps) {
      std::ostringstream msg;
      msg << "central_difference: time step " << dt_ << " s exceeds the stability limit "
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
  uOld_.assign(n, 0.0);
  problem_.applyPrescribed(0.0, u_.data(), v_.data());
  problem_.acceleration(0.0, u_.data(), f_.data(), a_.data());
  ++stats_.rhsEvaluations;
}

void CentralDifference::step(double dt) {
  const std::size_t n = problem_.dofs();
  const std::vector<char>& fixed = problem_.prescribed();
  const double tNew = t_ + dt;
  uOld_ = u_;
  for (std::size_t d = 0; d < n; ++d)
    if (!fixed[d]) {
      v_[d] += 0.5 * dt * a_[d];
      u_[d] += dt * v_[d];
    }
  problem_.applyPrescribed(tNew, u_.data(), v_.data());
  problem_.acceleration(tNew, u_.data(), fNext_.data(), a_.data());
  for (std::size_t d = 0; d < n; ++d)
    if (!fixed[d]) v_[d] += 0.5 * dt * a_[d];

  // External work by the trapezoid rule on the displacement increment (consistent with the scheme):
  // body force on free dofs, reactions -V L on prescribed ones.
  const double bOld = problem_.bodyAmplitude(t_), bNew = problem_.bodyAmplitude(tNew);
  const std::vector<double>& profile = problem_.bodyProfile();
  const ForceModel& model = problem_.model();
  for (std::size_t d = 0; d < n; ++d) {
    const double du = u_[d] - uOld_[d];
    if (fixed[d])
      work_ -= model.pointVolume(d / 2) * 0.5 * (f_[d] + fNext_[d]) * du;
    else if (!profile.empty())
      work_ += model.pointVolume(d / 2) * 0.5 * (bOld + bNew) * profile[d] * du;
  }
  f_.swap(fNext_);
  t_ = tNew;
  ++stats_.steps;
  ++stats_.rhsEvaluations;
}

void CentralDifference::advanceTo(double t) {
  require(std::isfinite(t) && t >= t_ - 1e-12 * std::abs(t_), "central_difference: cannot integrate backwards");
  const Stopwatch clock;
  // Whole steps, the last one landing exactly on t (shortened when t is not a multiple of the step:
  // the kick-drift-kick form allows a change of step).
  const double steps = std::ceil((t - t_) / dt_ - 1e-6);
  for (double k = 1; k < steps; ++k) step(dt_);
  if (steps >= 1) step(t - t_);
  for (std::size_t d = 0; d < u_.size(); ++d)
    if (!std::isfinite(u_[d]) || !std::isfinite(v_[d]))
      throw SolverFailure("central_difference: the solution is no longer finite at t = " + std::to_string(t_) + " s");
  stats_.seconds += clock.seconds();
}

}  // namespace peristep
