#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include "core/errors.hpp"
#include "dynamics_test_support.hpp"
#include "solvers/central_difference.hpp"

using namespace peristep;
using namespace peristep::testing;

namespace {

// Exact limit 2/sqrt(lambda_max(-A)) from a dense eigensolve of the rest-state tangent on free dofs.
double exactLimit(DynamicProblem& problem) {
  const std::vector<double> zero(problem.dofs(), 0.0);
  const Eigen::MatrixXd K = Eigen::MatrixXd(problem.model().tangent(zero.data())) / problem.density();
  std::vector<Eigen::Index> freeDofs;
  for (std::size_t d = 0; d < problem.dofs(); ++d)
    if (!problem.prescribed()[d]) freeDofs.push_back(static_cast<Eigen::Index>(d));
  const auto n = static_cast<Eigen::Index>(freeDofs.size());
  Eigen::MatrixXd A(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) A(i, j) = -K(freeDofs[i], freeDofs[j]);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  return 2.0 / std::sqrt(eig.eigenvalues().maxCoeff());
}

struct Case {
  PointCloud cloud = lattice(11, 9, 1e-3);
  std::unique_ptr<StateBasedModel> model;
  std::unique_ptr<DynamicProblem> problem;
  Case(double nu, double contrast) {
    StateBasedBondOptions o;
    o.horizon = 3e-3;
    o.stiffness.assign(cloud.size(), 1.0);
    for (std::size_t p = 0; p < cloud.size(); ++p)
      if (std::hypot(cloud.x[p], cloud.y[p]) < 2.1e-3) o.stiffness[p] = contrast;
    model = std::make_unique<StateBasedModel>(plexiglass(nu, 3e-3), buildStateBasedBonds(cloud, o));
    problem = std::make_unique<DynamicProblem>(*model, model->material().density);
    std::vector<std::uint32_t> left;
    for (std::size_t p = 0; p < cloud.size(); ++p)
      if (cloud.x[p] < -4e-3) left.insert(left.end(), {static_cast<std::uint32_t>(2 * p), static_cast<std::uint32_t>(2 * p + 1)});
    problem->prescribeVelocity(left, 0.0);
  }
};

}  // namespace

TEST_CASE("the stability estimate lies just below the exact central-difference limit", "[dynamics]") {
  const double nu = GENERATE(0.25, 0.22);
  const double contrast = GENERATE(1.0, 1e3);
  Case c(nu, contrast);
  const double exact = exactLimit(*c.problem);
  const StabilityEstimate est = estimateStabilityLimit(*c.problem);
  INFO("nu " << nu << ", contrast " << contrast << ": estimate " << est.criticalStep << " s, exact " << exact << " s");
  CHECK(est.criticalStep <= exact * (1 + 1e-10));
  CHECK(est.criticalStep >= 0.95 * exact);
}

TEST_CASE("a time step above the stability limit is refused, or substepped on request", "[dynamics]") {
  Case c(0.25, 1.0);
  c.problem->setInitialState(randomField(c.problem->dofs(), 1e-7, 1), std::vector<double>(c.problem->dofs(), 0.0));
  const double limit = estimateStabilityLimit(*c.problem).criticalStep;
  IntegratorOptions o;
  o.timeStep = 1.05 * limit;
  try {
    makeTimeIntegrator("centralDifference", *c.problem, o);
    FAIL("a step above the limit was accepted");
  } catch (const InvalidInput& e) {
    CHECK_THAT(e.what(), Catch::Contains("stability limit"));
  }

  o.allowSubsteps = true;
  CentralDifference split(*c.problem, o);
  CHECK(split.internalStep() < limit);
  CHECK(split.internalStep() == Approx(o.timeStep / 2));
  split.advanceTo(200 * o.timeStep);
  // Same answer as asking for the smaller step directly.
  IntegratorOptions small;
  small.timeStep = split.internalStep();
  CentralDifference direct(*c.problem, small);
  direct.advanceTo(200 * o.timeStep);
  for (std::size_t d = 0; d < c.problem->dofs(); ++d) CHECK(split.displacement()[d] == Approx(direct.displacement()[d]).margin(1e-18));
  CHECK(split.stats().steps == 400);
}

TEST_CASE("just below the limit the scheme stays bounded", "[dynamics]") {
  Case c(0.22, 1.0);
  const std::vector<double> u0 = randomField(c.problem->dofs(), 1e-7, 2);
  c.problem->setInitialState(u0, std::vector<double>(c.problem->dofs(), 0.0));
  IntegratorOptions o;
  // 0.99 of the exact limit, or the estimate when that is (slightly, conservatively) smaller.
  o.timeStep = std::min(0.99 * exactLimit(*c.problem), estimateStabilityLimit(*c.problem).criticalStep);
  CentralDifference cd(*c.problem, o);
  double largest = 0;
  for (int k = 1; k <= 50; ++k) {
    cd.advanceTo(100 * k * o.timeStep);
    for (std::size_t d = 0; d < c.problem->dofs(); ++d) largest = std::max(largest, std::abs(cd.displacement()[d]));
  }
  // A mode beyond the limit would grow by orders of magnitude over 5000 steps.
  CHECK(largest < 100 * 1e-7);
}
