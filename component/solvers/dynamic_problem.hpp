#pragma once
// The semi-discrete equation of motion rho u'' = L(u) + b(t) (001:(12), (30)) on a point cloud, with
// prescribed-velocity boundary dofs and a separable body force. Shared by every time integrator.
// The loads carry a scale s (1 unless rescaled): prescribed dofs move at s times their velocity and the
// body force is s amplitude(t). A co-simulation input changes s between communication steps.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "models/force_model.hpp"

namespace peristep {

class DynamicProblem {
 public:
  DynamicProblem(ForceModel& model, double density);

  // Dofs (2 p + component) moving at a constant velocity: u(t) = u(0) + velocity t (velocity 0 holds them).
  void prescribeVelocity(const std::vector<std::uint32_t>& dofs, double velocity);
  // A density per point [kg/m^3] instead of the one given to the constructor (a specimen's map).
  void setDensity(std::vector<double> perPoint);
  // b(x_p, t) = amplitude(t) * profile[dof] [N/m^3].
  void setBodyForce(std::vector<double> profile, std::function<double(double)> amplitude);
  // Initial displacement and velocity (interleaved, 2 N each); prescribed dofs take their own velocity.
  void setInitialState(std::vector<double> u0, std::vector<double> v0);

  // From time t on, the loads are scaled by `scale`: prescribed dofs continue from their values in u
  // at t with scale times their velocity, the body force becomes scale amplitude(t).
  void rescaleLoads(double scale, double t, const double* u);
  // The prescribed path u_d(t) = start_d + scale velocity_d (t - since), exactly (for checkpoints);
  // start holds one value per entry of prescribedDofs().
  struct LoadPath {
    double scale = 1, since = 0;
    std::vector<double> start;
  };
  LoadPath loadPath() const;
  void setLoadPath(const LoadPath& path);
  double loadScale() const { return scale_; }

  ForceModel& model() { return model_; }
  // Loops over dofs use threads only above this size (below, a parallel region costs more than it saves).
  bool threaded() const { return dofs() >= 40000; }
  std::size_t dofs() const { return 2 * model_.points(); }
  double density() const { return density_; }               // the uniform density, unless...
  const std::vector<double>& pointDensity() const { return rho_; }  // ...one per point is set (else empty)
  const std::vector<char>& prescribed() const { return prescribed_; }   // 1 on prescribed dofs
  const std::vector<std::uint32_t>& prescribedDofs() const { return prescribedList_; }
  const std::vector<double>& prescribedVelocity() const { return velocity_; }
  const std::vector<double>& initialDisplacement() const { return u0_; }
  const std::vector<double>& initialVelocity() const { return v0_; }

  // f = L(u); a = (f + b(t))/rho on free dofs and 0 on prescribed ones.
  void acceleration(double t, const double* u, double* f, double* a);
  // da = (dL/du du)/rho on free dofs, 0 on prescribed ones.
  void accelerationDerivative(const double* u, const double* du, double* da);
  // Prescribed dofs of (u, v) set to their values at time t.
  void applyPrescribed(double t, double* u, double* v) const;
  // Rate of work of the body force and of the reactions that hold the prescribed dofs on their path:
  // P = sum_free V b . v + sum_prescribed (-V L) . v, with f = L(u).
  double externalPower(double t, const double* f, const double* v) const;
  double kineticEnergy(const double* v) const;
  double bodyAmplitude(double t) const { return bodyProfile_.empty() ? 0.0 : scale_ * amplitude_(t); }
  const std::vector<double>& bodyProfile() const { return bodyProfile_; }

 private:
  ForceModel& model_;
  double density_;
  std::vector<double> rho_, invRho_;  // per point, when set
  std::vector<char> prescribed_;
  std::vector<std::uint32_t> prescribedList_;
  std::vector<double> velocity_;
  std::vector<double> bodyProfile_;
  std::function<double(double)> amplitude_;
  std::vector<double> u0_, v0_;
  double scale_ = 1, since_ = 0;
  std::vector<double> pathStart_;  // per dof; read on prescribed dofs only (u0_ until rescaled)
};

}  // namespace peristep
