#include "solvers/dynamic_problem.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace peristep {

DynamicProblem::DynamicProblem(ForceModel& model, double density) : model_(model), density_(density) {
  require(std::isfinite(density) && density > 0, "dynamic problem: density must be positive");
  require(model.points() > 0, "dynamic problem: the model has no points");
  prescribed_.assign(dofs(), 0);
  velocity_.assign(dofs(), 0.0);
  u0_.assign(dofs(), 0.0);
  v0_.assign(dofs(), 0.0);
  pathStart_ = u0_;
}

void DynamicProblem::prescribeVelocity(const std::vector<std::uint32_t>& dofs, double velocity) {
  require(std::isfinite(velocity), "dynamic problem: prescribed velocity must be finite");
  for (const std::uint32_t d : dofs) {
    require(d < this->dofs(), "dynamic problem: prescribed dof " + std::to_string(d) + " out of range");
    if (!prescribed_[d]) prescribedList_.push_back(d);
    prescribed_[d] = 1;
    velocity_[d] = velocity;
    v0_[d] = velocity;
  }
}

void DynamicProblem::setDensity(std::vector<double> perPoint) {
  require(perPoint.size() == model_.points(), "dynamic problem: density needs one value per point");
  invRho_.clear();
  for (const double rho : perPoint) {
    require(std::isfinite(rho) && rho > 0, "dynamic problem: density must be positive");
    invRho_.push_back(1.0 / rho);
  }
  rho_ = std::move(perPoint);
}

void DynamicProblem::setBodyForce(std::vector<double> profile, std::function<double(double)> amplitude) {
  require(profile.size() == dofs(), "dynamic problem: body force profile needs one value per dof");
  require(static_cast<bool>(amplitude), "dynamic problem: body force needs an amplitude function");
  bodyProfile_ = std::move(profile);
  amplitude_ = std::move(amplitude);
}

void DynamicProblem::setInitialState(std::vector<double> u0, std::vector<double> v0) {
  require(u0.size() == dofs() && v0.size() == dofs(), "dynamic problem: initial state needs 2 values per point");
  for (std::size_t d = 0; d < dofs(); ++d) {
    require(std::isfinite(u0[d]) && std::isfinite(v0[d]), "dynamic problem: initial state must be finite");
    if (prescribed_[d]) v0[d] = velocity_[d];
  }
  u0_ = std::move(u0);
  v0_ = std::move(v0);
  pathStart_ = u0_;
}

void DynamicProblem::rescaleLoads(double scale, double t, const double* u) {
  require(std::isfinite(scale) && std::isfinite(t), "dynamic problem: load scale and time must be finite");
  for (const std::uint32_t d : prescribedList_) pathStart_[d] = u[d];
  scale_ = scale;
  since_ = t;
}

DynamicProblem::LoadPath DynamicProblem::loadPath() const {
  LoadPath p{scale_, since_, {}};
  p.start.reserve(prescribedList_.size());
  for (const std::uint32_t d : prescribedList_) p.start.push_back(pathStart_[d]);
  return p;
}

void DynamicProblem::setLoadPath(const LoadPath& p) {
  require(p.start.size() == prescribedList_.size(), "dynamic problem: the load path needs one start value per "
                                                    "prescribed dof");
  require(std::isfinite(p.scale) && std::isfinite(p.since), "dynamic problem: load scale and time must be finite");
  for (std::size_t k = 0; k < prescribedList_.size(); ++k) pathStart_[prescribedList_[k]] = p.start[k];
  scale_ = p.scale;
  since_ = p.since;
}

void DynamicProblem::acceleration(double t, const double* u, double* f, double* a) {
  model_.force(u, f);
  const double amp = bodyAmplitude(t), inv = 1.0 / density_;
  const auto n = static_cast<std::ptrdiff_t>(dofs());
  const double* b = bodyProfile_.empty() ? nullptr : bodyProfile_.data();
  const double* invRho = invRho_.empty() ? nullptr : invRho_.data();
#pragma omp parallel for schedule(static) if (threaded())
  for (std::ptrdiff_t d = 0; d < n; ++d)
    a[d] = prescribed_[d] ? 0.0 : (invRho ? invRho[d / 2] : inv) * (f[d] + (b ? amp * b[d] : 0.0));
}

void DynamicProblem::accelerationDerivative(const double* u, const double* du, double* da) {
  model_.forceDerivative(u, du, da);
  const double inv = 1.0 / density_;
  for (std::size_t d = 0; d < dofs(); ++d)
    da[d] = prescribed_[d] ? 0.0 : (invRho_.empty() ? inv : invRho_[d / 2]) * da[d];
}

void DynamicProblem::applyPrescribed(double t, double* u, double* v) const {
  for (const std::uint32_t d : prescribedList_) {
    u[d] = pathStart_[d] + scale_ * velocity_[d] * (t - since_);
    v[d] = scale_ * velocity_[d];
  }
}

double DynamicProblem::externalPower(double t, const double* f, const double* v) const {
  const double amp = bodyAmplitude(t);
  double p = 0;
  for (std::size_t d = 0; d < dofs(); ++d) {
    if (prescribed_[d])
      p -= model_.pointVolume(d / 2) * f[d] * v[d];
    else if (!bodyProfile_.empty())
      p += model_.pointVolume(d / 2) * amp * bodyProfile_[d] * v[d];
  }
  return p;
}

double DynamicProblem::kineticEnergy(const double* v) const {
  double e = 0;
  if (!rho_.empty()) {
    for (std::size_t d = 0; d < dofs(); ++d) e += rho_[d / 2] * model_.pointVolume(d / 2) * v[d] * v[d];
    return 0.5 * e;
  }
  for (std::size_t d = 0; d < dofs(); ++d) e += model_.pointVolume(d / 2) * v[d] * v[d];
  return 0.5 * density_ * e;
}

}  // namespace peristep
