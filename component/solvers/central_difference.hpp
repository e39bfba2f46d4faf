#pragma once
// Explicit central difference 001:(35)-(36), written in the equivalent kick-drift-kick form
//   v^{k+1/2} = v^k + dt/2 a^k,  u^{k+1} = u^k + dt v^{k+1/2},  v^{k+1} = v^{k+1/2} + dt/2 a^{k+1},
// whose displacements are those of 001:(35)-(36) (its v^{k+1} is our v^{k+1/2}); the form keeps a
// velocity at whole steps for the energy and lets the last step of an interval be shortened.
#include <vector>

#include "solvers/stability_limit.hpp"
#include "solvers/time_integrator.hpp"

namespace peristep {

class CentralDifference final : public TimeIntegrator {
 public:
  // Estimates the stability limit once. A step above it throws InvalidInput naming the limit, unless
  // options.allowSubsteps: then every step is split into equal substeps below 0.95 of the limit.
  CentralDifference(DynamicProblem& problem, const IntegratorOptions& options);

  std::string_view name() const override { return "centralDifference"; }
  void advanceTo(double t) override;
  double time() const override { return t_; }
  const double* displacement() const override { return u_.data(); }
  const double* velocity() const override { return v_.data(); }
  double externalWork() const override { return work_; }
  IntegratorStats stats() const override { return stats_; }
  void setState(double t, const double* u, const double* v, double work) override;

  const StabilityEstimate& stability() const { return stability_; }
  double internalStep() const { return dt_; }  // the step actually taken (after any substepping)

 private:
  void step(double dt);

  DynamicProblem& problem_;
  StabilityEstimate stability_;
  double dt_ = 0, t_ = 0, work_ = 0;
  std::vector<double> u_, v_, a_, f_, fNext_, volume_;  // volume_: per dof
  IntegratorStats stats_;
};

}  // namespace peristep
