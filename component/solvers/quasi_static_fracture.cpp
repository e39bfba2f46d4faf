#include "solvers/quasi_static_fracture.hpp"

#include <cmath>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "models/lps_material.hpp"
#include "solvers/gmres.hpp"

namespace peristep {
namespace {

// Relative stiffness of the springs that hold points with broken bonds near their last position. They
// remove the rigid-body modes of floating fragments and the mechanisms of nearly detached points
// (no singular factorization, no NaN) and perturb the solution by about this relative amount.
constexpr double kSpringRatio = 1e-8;
constexpr int kMaxSubIterations = 100000;
constexpr double kKrylovTolerance = 1e-10;
constexpr int kMaxKrylovIterations = 40;
// Refactorize instead of iterating when the last GMRES solve cost more than this many iterations.
constexpr int kRefactorizeAfter = 8;

}  // namespace

QuasiStaticFracture::QuasiStaticFracture(std::shared_ptr<const LpsDiscretization> disc, FractureMaterial material,
                                         BondState bonds, std::vector<double> unitCollarDisplacement,
                                         const std::string& solverName)
    : disc_(std::move(disc)),
      material_(std::move(material)),
      bonds_(std::move(bonds)),
      unitCollar_(std::move(unitCollarDisplacement)),
      solver_(makeLinearSolver(solverName)) {
  const std::size_t n = disc_->cloud.size();
  require(material_.lambda.size() == n && material_.mu.size() == n && material_.fractureEnergy.size() == n,
          "fracture material must have one value per point");
  require(unitCollar_.size() == 2 * n, "collar displacement must have two components per point");
  require(bonds_.bonds() == disc_->neighbours.bonds(), "bond state does not match the neighbour lists");
  u_.assign(2 * n, 0.0);
  x_.assign(static_cast<std::size_t>(disc_->dofs.size), 0.0);
  assemble();
}

void QuasiStaticFracture::assemble() {
  const PointCloud& c = disc_->cloud;
  const Neighbours& nb = disc_->neighbours;
  system_ = assembleLps(c, nb, disc_->weights, material_.lambda, material_.mu, disc_->dofs, &bonds_.intact);
  stabilized_.assign(c.size(), 0);
  for (std::size_t p : c.domain) {
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k)
      if (!bonds_.intact[k]) stabilized_[p] = 1;
    if (!stabilized_[p]) continue;
    const double spring = kSpringRatio * 24.0 * material_.mu[p] / (c.delta * c.delta);
    for (int a = 0; a < 2; ++a) {
      const std::int64_t row = disc_->dofs.u[p] + a;
      for (std::int64_t k = system_.A.rowStart[row]; k < system_.A.rowStart[row + 1]; ++k)
        if (system_.A.col[k] == row) system_.A.value[k] += spring;
    }
  }
  factorizationCurrent_ = false;
}

void QuasiStaticFracture::solveCurrent(LoadStepReport& report) {
  const PointCloud& c = disc_->cloud;
  const DofMap& d = disc_->dofs;
  std::vector<double> g(unitCollar_.size()), rhs(x_.size());
  for (std::size_t k = 0; k < g.size(); ++k) g[k] = load_ * unitCollar_[k];
  system_.B.multiply(g, rhs);
  for (double& v : rhs) v = -v;
  for (std::size_t p : c.domain)
    if (stabilized_[p])
      for (int a = 0; a < 2; ++a)
        rhs[static_cast<std::size_t>(d.u[p] + a)] +=
            kSpringRatio * 24.0 * material_.mu[p] / (c.delta * c.delta) * u_[2 * p + static_cast<std::size_t>(a)];

  bool solved = false;
  if (factorizationCurrent_) {
    solver_->solve(rhs, x_);
    solved = true;
  } else if (analyzed_ && lastKrylovIterations_ <= kRefactorizeAfter) {
    // An older factorization of a nearby matrix (a few bonds broken since): use it as a preconditioner.
    const GmresResult r = gmres(system_.A, *solver_, rhs, x_, kKrylovTolerance, kMaxKrylovIterations);
    report.krylovIterations += r.iterations;
    lastKrylovIterations_ = r.iterations;
    solved = r.converged;
  }
  if (!solved) {
    if (!analyzed_) solver_->analyze(system_.A);
    analyzed_ = true;
    solver_->factorize(system_.A);
    factorizationCurrent_ = true;
    lastKrylovIterations_ = 0;
    ++report.factorizations;
    solver_->solve(rhs, x_);
  }
  for (double v : x_)
    if (!std::isfinite(v)) throw SolverFailure("fracture solve produced a non-finite displacement");
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (d.u[p] >= 0) {
      u_[2 * p] = x_[static_cast<std::size_t>(d.u[p])];
      u_[2 * p + 1] = x_[static_cast<std::size_t>(d.u[p]) + 1];
    } else {
      u_[2 * p] = c.isVoid(p) ? 0.0 : g[2 * p];
      u_[2 * p + 1] = c.isVoid(p) ? 0.0 : g[2 * p + 1];
    }
  }
}

LoadStepReport QuasiStaticFracture::advance(double load) {
  require(std::isfinite(load), "load must be finite");
  load_ = load;
  LoadStepReport report;
  // Every load step starts from a factorization of the current matrix, so that a run restored from a
  // checkpoint between load steps repeats the original bit for bit. Sub-iterations reuse it.
  if (!factorizationCurrent_) {
    if (!analyzed_) solver_->analyze(system_.A);
    analyzed_ = true;
    solver_->factorize(system_.A);
    factorizationCurrent_ = true;
    ++report.factorizations;
  }
  for (;;) {
    solveCurrent(report);
    ++report.subIterations;
    const std::vector<std::size_t> fresh = breakOverstretched(bonds_, disc_->cloud, disc_->neighbours, u_);
    if (fresh.empty()) break;
    brokenByLoading_.insert(brokenByLoading_.end(), fresh.begin(), fresh.end());
    report.newlyBroken += fresh.size();
    assemble();
    if (report.subIterations >= kMaxSubIterations)
      throw SolverFailure("no equilibrium after " + std::to_string(kMaxSubIterations) + " sub-iterations");
  }
  return report;
}

std::array<double, 2> QuasiStaticFracture::collarForce(const std::vector<std::uint8_t>& collar) const {
  const PointCloud& c = disc_->cloud;
  const Neighbours& nb = disc_->neighbours;
  const DofMap& d = disc_->dofs;
  const auto theta = [&](std::size_t p) { return d.theta[p] >= 0 ? x_[static_cast<std::size_t>(d.theta[p])] : 0.0; };
  std::array<double, 2> F{0, 0};
  for (std::size_t p : c.domain)
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      const std::uint32_t q = nb.index[k];
      if (!collar[q] || !bonds_.intact[k]) continue;
      // Force of bond p-q on p: the negated summand of 000:(3.19).
      const double z[2] = {c.x[q] - c.x[p], c.y[q] - c.y[p]};
      const double r2 = z[0] * z[0] + z[1] * z[1];
      const double Kw = 3.0 / (M_PI * std::pow(c.delta, 3) * std::sqrt(r2)) * disc_->weights[k];
      const double lam = harmonicMean(material_.lambda[p], material_.lambda[q]);
      const double m = harmonicMean(material_.mu[p], material_.mu[q]);
      const double du[2] = {u_[2 * q] - u_[2 * p], u_[2 * q + 1] - u_[2 * p + 1]};
      const double zdu = z[0] * du[0] + z[1] * du[1];
      for (int a = 0; a < 2; ++a)
        F[static_cast<std::size_t>(a)] += c.h * c.h * Kw * ((lam - m) * z[a] * (theta(p) + theta(q)) + 8.0 * m * z[a] * zdu / r2);
    }
  return F;
}

std::vector<std::uint8_t> QuasiStaticFracture::saveState() const {
  ByteWriter w;
  w.put(load_);
  w.putArray(u_);
  w.putArray(x_);
  w.putArray(bonds_.intact);
  w.putArray(brokenByLoading_);
  return w.take();
}

void QuasiStaticFracture::restoreState(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes);
  const double load = r.get<double>();
  auto u = r.getArray<double>(u_.size());
  auto x = r.getArray<double>(x_.size());
  auto intact = r.getArray<std::uint8_t>(bonds_.intact.size());
  auto broken = r.getArray<std::size_t>();
  r.expectEnd();
  load_ = load;
  u_ = std::move(u);
  x_ = std::move(x);
  bonds_.intact = std::move(intact);
  brokenByLoading_ = std::move(broken);
  assemble();
}

}  // namespace peristep
