#include "solvers/static_lps.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/timer.hpp"
#include "models/lps_material.hpp"

namespace peristep {

StaticLps::StaticLps(std::shared_ptr<const LpsDiscretization> disc, const ElasticScene& scene,
                     LinearSolverKind solver)
    : disc_(std::move(disc)), scene_(scene), solver_(makeLinearSolver(solver)) {
  const PointCloud& c = disc_->cloud;
  const DofMap& d = disc_->dofs;
  const double nu = scene.poissonRatio();
  validateElastic(1.0, nu);

  Stopwatch clock;
  std::vector<double> lambda(c.size()), mu(c.size()), g(2 * c.size(), 0.0);
  for (std::size_t p = 0; p < c.size(); ++p) {
    const double E = scene.youngsModulus(c.x[p], c.y[p]);
    if (!(std::isfinite(E) && E > 0)) {
      std::ostringstream msg;
      msg << "Young's modulus must be positive and finite: E = " << E << " at (" << c.x[p] << ", " << c.y[p] << ")";
      throw InvalidInput(msg.str());
    }
    const Lame l = planeStrain(E, nu);
    lambda[p] = l.lambda;
    mu[p] = l.mu;
    if (d.u[p] < 0) {
      const Vec2 u = scene.displacement(c.x[p], c.y[p]);
      g[2 * p] = u[0];
      g[2 * p + 1] = u[1];
    }
  }
  system_ = assembleLps(c, disc_->neighbours, disc_->weights, lambda, mu, d);

  // rhs = f - B g: body force on the momentum rows, collar data moved to the right.
  rhs0_.assign(static_cast<std::size_t>(d.size), 0.0);
  system_.B.multiply(g, rhs0_);
  for (double& v : rhs0_) v = -v;
  for (std::size_t p : c.domain) {
    const Vec2 f = scene.bodyForce(c.x[p], c.y[p]);
    rhs0_[static_cast<std::size_t>(d.u[p])] += f[0];
    rhs0_[static_cast<std::size_t>(d.u[p]) + 1] += f[1];
  }
  times_.assembly = clock.lap();

  solver_->analyze(system_.A);
  solver_->factorize(system_.A);
  times_.factorization = clock.lap();
}

void StaticLps::solve(double loadFactor) {
  require(std::isfinite(loadFactor), "load factor must be finite");
  Stopwatch clock;
  std::vector<double> b(rhs0_.size()), x(rhs0_.size());
  for (std::size_t k = 0; k < b.size(); ++k) b[k] = loadFactor * rhs0_[k];
  solver_->solve(b, x);
  const PointCloud& c = disc_->cloud;
  ux_.resize(c.domain.size());
  uy_.resize(c.domain.size());
  for (std::size_t i = 0; i < c.domain.size(); ++i) {
    const auto k = static_cast<std::size_t>(disc_->dofs.u[c.domain[i]]);
    ux_[i] = x[k];
    uy_[i] = x[k + 1];
  }
  load_ = loadFactor;
  times_.solve = clock.lap();
}

double StaticLps::errorL2At(const std::vector<double>& ux, const std::vector<double>& uy, double load) const {
  const PointCloud& c = disc_->cloud;
  require(ux.size() == c.domain.size() && uy.size() == c.domain.size(), "no displacement to compare: solve first");
  double sum = 0.0;
  for (std::size_t i = 0; i < c.domain.size(); ++i) {
    const std::size_t p = c.domain[i];
    const Vec2 u0 = scene_.displacement(c.x[p], c.y[p]);
    const double ex = ux[i] - load * u0[0], ey = uy[i] - load * u0[1];
    sum += ex * ex + ey * ey;
  }
  return std::sqrt(sum * c.h * c.h);
}

}  // namespace peristep
