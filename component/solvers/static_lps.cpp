#include "solvers/static_lps.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/timer.hpp"
#include "models/collar_force.hpp"
#include "models/lps_material.hpp"
#include "models/unheld_pieces.hpp"

namespace peristep {

StaticLps::StaticLps(std::shared_ptr<const LpsDiscretization> disc, const ElasticScene& scene,
                     LinearSolverKind solver, std::vector<std::uint8_t> intact)
    : disc_(std::move(disc)), scene_(&scene) {
  loading_.intact = std::move(intact);
  const PointCloud& c = disc_->cloud;
  const double nu = scene.poissonRatio();
  validateElastic(1.0, nu);

  Stopwatch clock;
  StaticLoading& l = loading_;
  l.lambda.resize(c.size());
  l.mu.resize(c.size());
  l.unitCollar.assign(2 * c.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    const double E = scene.youngsModulus(c.x[p], c.y[p]);
    if (!(std::isfinite(E) && E > 0)) {
      std::ostringstream msg;
      msg << "Young's modulus must be positive and finite: E = " << E << " at (" << c.x[p] << ", " << c.y[p] << ")";
      throw InvalidInput(msg.str());
    }
    const Lame lame = planeStrain(E, nu);
    l.lambda[p] = lame.lambda;
    l.mu[p] = lame.mu;
    if (disc_->dofs.u[p] < 0) {
      const Vec2 u = scene.displacement(c.x[p], c.y[p]);
      l.unitCollar[2 * p] = u[0];
      l.unitCollar[2 * p + 1] = u[1];
    }
  }
  times_.assembly = clock.lap();
  const std::vector<std::size_t> unheld = setUp(solver);
  clock.lap();
  for (std::size_t p : unheld) {
    const Vec2 f = scene.bodyForce(c.x[p], c.y[p]);
    if (f[0] != 0.0 || f[1] != 0.0) {
      std::ostringstream msg;
      msg << "a piece of the specimen that no bond holds to the collar carries a body force at (" << c.x[p] << ", "
          << c.y[p] << "): it has no equilibrium";
      throw InvalidInput(msg.str());
    }
  }
  // Body force on the momentum rows.
  for (std::size_t p : c.domain) {
    const Vec2 f = scene.bodyForce(c.x[p], c.y[p]);
    rhs0_[static_cast<std::size_t>(disc_->dofs.u[p])] += f[0];
    rhs0_[static_cast<std::size_t>(disc_->dofs.u[p]) + 1] += f[1];
  }
  times_.assembly += clock.lap();
}

StaticLps::StaticLps(std::shared_ptr<const LpsDiscretization> disc, StaticLoading loading, LinearSolverKind solver)
    : disc_(std::move(disc)), loading_(std::move(loading)) {
  const std::size_t n = disc_->cloud.size();
  require(loading_.lambda.size() == n && loading_.mu.size() == n && loading_.unitCollar.size() == 2 * n &&
              (loading_.intact.empty() || loading_.intact.size() == disc_->neighbours.index.size()),
          "internal error: static loading does not match the cloud");
  setUp(solver);
}

std::vector<std::size_t> StaticLps::setUp(LinearSolverKind solver) {
  const DofMap& d = disc_->dofs;
  Stopwatch clock;
  const std::vector<std::uint8_t>* intact = loading_.intact.empty() ? nullptr : &loading_.intact;
  system_ = assembleLps(disc_->cloud, disc_->neighbours, disc_->weights, loading_.lambda, loading_.mu, d, intact);
  // rhs = f - B g at load 1: the collar data moved to the right (the body force is added by the caller).
  rhs0_.assign(static_cast<std::size_t>(d.size), 0.0);
  system_.B.multiply(loading_.unitCollar, rhs0_);
  for (double& v : rhs0_) v = -v;
  std::vector<std::size_t> unheld = unheldPoints(disc_->cloud, disc_->neighbours, intact);
  holdAtRest(system_.A, d, unheld);
  times_.assembly += clock.lap();

  solver_ = makeLinearSolver(solver);
  solver_->analyze(system_.A);
  solver_->factorize(system_.A);
  times_.factorization = clock.lap();
  return unheld;
}

void StaticLps::solve(double loadFactor) {
  require(std::isfinite(loadFactor), "load factor must be finite");
  Stopwatch clock;
  std::vector<double> b(rhs0_.size());
  x_.assign(rhs0_.size(), 0.0);
  for (std::size_t k = 0; k < b.size(); ++k) b[k] = loadFactor * rhs0_[k];
  solver_->solve(b, x_);
  const PointCloud& c = disc_->cloud;
  ux_.resize(c.domain.size());
  uy_.resize(c.domain.size());
  for (std::size_t i = 0; i < c.domain.size(); ++i) {
    const auto k = static_cast<std::size_t>(disc_->dofs.u[c.domain[i]]);
    ux_[i] = x_[k];
    uy_[i] = x_[k + 1];
  }
  load_ = loadFactor;
  u_.assign(2 * c.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p)
    for (std::size_t a = 0; a < 2; ++a) {
      const std::int64_t k = disc_->dofs.u[p];
      u_[2 * p + a] = k >= 0 ? x_[static_cast<std::size_t>(k) + a] : loadFactor * loading_.unitCollar[2 * p + a];
    }
  times_.solve = clock.lap();
}

std::array<double, 2> StaticLps::collarForce(const std::vector<std::uint8_t>& collar) const {
  require(!x_.empty(), "no displacement yet: solve first");
  return peristep::collarForce(*disc_, loading_.lambda, loading_.mu, u_, x_, collar,
                               loading_.intact.empty() ? nullptr : &loading_.intact);
}

double StaticLps::errorL2At(const std::vector<double>& ux, const std::vector<double>& uy, double load) const {
  require(scene_ != nullptr, "internal error: no exact solution to compare with");
  const PointCloud& c = disc_->cloud;
  require(ux.size() == c.domain.size() && uy.size() == c.domain.size(), "no displacement to compare: solve first");
  double sum = 0.0;
  for (std::size_t i = 0; i < c.domain.size(); ++i) {
    const std::size_t p = c.domain[i];
    const Vec2 u0 = scene_->displacement(c.x[p], c.y[p]);
    const double ex = ux[i] - load * u0[0], ey = uy[i] - load * u0[1];
    sum += ex * ex + ey * ey;
  }
  return std::sqrt(sum * c.h * c.h);
}

}  // namespace peristep
