// Kernel learning (003 Sec. 4) on data made by the learned-LPS operator itself: the fit must give back the
// kernel and the moduli that made the data.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "learning/kernel_fit.hpp"
#include "learning/learned_lps_force_model.hpp"
#include "solvers/dynamic_problem.hpp"
#include "solvers/stability_limit.hpp"
#include "learning_support.hpp"

using namespace peristep::learning;
using namespace peristep::learning::testing;

namespace {

const PeriodicLattice kLattice{20, 20, 5.0, 5.0};
const double kDelta = 15.0;  // 3 h

std::vector<double> unitWeights(const std::vector<StaticSample>& s) {
  std::vector<double> w;
  for (const auto& x : s) w.push_back(1.0 / rms(x.b));
  return w;
}

}  // namespace

TEST_CASE("the true kernel changes sign and satisfies the solvability constraints 003:(37)", "[learning]") {
  const Truth t = syntheticTruth(kDelta);
  const LatticeStencil st = makeLatticeStencil(5.0, 5.0, kDelta);
  double kmin = INFINITY, kmax = -INFINITY;
  for (int i = 1; i < 100; ++i) {
    const double K = t.kernel(kDelta * i / 100.0);
    kmin = std::min(kmin, K), kmax = std::max(kmax, K);
  }
  CHECK(kmin < 0);
  CHECK(kmax > 0);
  CHECK(checkSolvability(kLattice, st, t.kernel, t.lambda, t.mu).solvable());
  // A model with lambda + mu < 0 is rejected.
  CHECK_FALSE(checkSolvability(kLattice, st, t.kernel, -0.8, 0.7).solvable());
}

TEST_CASE("symbol solutions satisfy the operator of 003:(17)-(18), and the residual columns agree with it",
          "[learning]") {
  const Truth t = syntheticTruth(kDelta);
  const LatticeStencil st = makeLatticeStencil(5.0, 5.0, kDelta);
  const std::vector<StaticSample> samples = cosineSamples(kLattice, st, t);
  REQUIRE(samples.size() == 70);
  double worst = 0;
  for (const auto& s : samples) {
    const std::vector<double> L = applyLearnedLps(kLattice, st, t.kernel, t.lambda, t.mu, s.u);
    for (std::size_t i = 0; i < L.size(); ++i) worst = std::max(worst, std::abs(L[i] - s.b[i]));
  }
  CHECK(worst < 1e-12);  // |b| <= 1
  StaticResidual res(kLattice, st, 3, {samples[7], samples[40]}, {1.0, 1.0});
  std::vector<double> c1, c2;
  res.columns(t.kernel.alpha, t.kernel.D, c1, c2);
  double diff = 0;
  for (std::size_t i = 0; i < c1.size(); ++i) diff = std::max(diff, std::abs(t.lambda * c1[i] + t.mu * c2[i] - res.rhs()[i]));
  CHECK(diff < 1e-12);
}

TEST_CASE("without noise the fit recovers kernel, lambda and mu to 1e-8", "[learning]") {
  const Truth t = syntheticTruth(kDelta);
  const LatticeStencil st = makeLatticeStencil(5.0, 5.0, kDelta);
  std::vector<StaticSample> samples = cosineSamples(kLattice, st, t);
  const std::vector<double> w = unitWeights(samples);
  StaticResidual res(kLattice, st, 3, std::move(samples), w);
  const KernelFit fit = fitKernel(res);
  INFO("iterations " << fit.iterations << ", evaluations " << fit.evaluations << ", residual " << fit.relativeResidual);
  REQUIRE(fit.converged);
  CHECK(std::abs(fit.lambda - t.lambda) < 1e-8 * std::abs(t.lambda));
  CHECK(std::abs(fit.mu - t.mu) < 1e-8 * t.mu);
  CHECK(std::abs(fit.kernel.alpha - t.kernel.alpha) < 1e-8);
  double Dmax = 0, Derr = 0;
  for (int k = 0; k <= 3; ++k) {
    Dmax = std::max(Dmax, std::abs(t.kernel.D[k]));
    Derr = std::max(Derr, std::abs(fit.kernel.D[k] - t.kernel.D[k]));
  }
  CHECK(Derr < 1e-8 * Dmax);
  CHECK(fit.kernel.weightedVolume() == Approx(1.0).epsilon(1e-12));  // the reported normalization
}

TEST_CASE("the nonnegative fit recovers a nonnegative kernel to 1e-8 and keeps K >= 0 on a sign-changing one",
          "[learning]") {
  const LatticeStencil st = makeLatticeStencil(5.0, 5.0, kDelta);
  Truth t{BernsteinKernel{kDelta, 0.5, {0.1, 0.4, 0.2, 0.3}}, -0.2, 0.7};  // xi_k, all >= 0
  for (int k = 0; k <= 3; ++k) t.kernel.D[static_cast<std::size_t>(k)] /= t.kernel.weightedVolumeCoefficient(k);
  std::vector<StaticSample> samples = cosineSamples(kLattice, st, t);
  const std::vector<double> w = unitWeights(samples);
  StaticResidual res(kLattice, st, 3, std::move(samples), w);
  const KernelFit fit = fitKernel(res, {.nonnegative = true});
  INFO("iterations " << fit.iterations << ", residual " << fit.relativeResidual);
  REQUIRE(fit.converged);
  CHECK(std::abs(fit.lambda - t.lambda) < 1e-8 * std::abs(t.lambda));
  CHECK(std::abs(fit.mu - t.mu) < 1e-8 * t.mu);
  CHECK(std::abs(fit.kernel.alpha - t.kernel.alpha) < 1e-8);
  for (int k = 0; k <= 3; ++k) CHECK(std::abs(fit.kernel.D[k] - t.kernel.D[k]) < 1e-8 * t.kernel.D[1]);

  // The sign-changing truth cannot be matched: the fit stays at K >= 0 and leaves a residual.
  const Truth s = syntheticTruth(kDelta);
  std::vector<StaticSample> signedSamples = cosineSamples(kLattice, st, s);
  const std::vector<double> ws = unitWeights(signedSamples);
  StaticResidual signedRes(kLattice, st, 3, std::move(signedSamples), ws);
  const KernelFit nn = fitKernel(signedRes, {.nonnegative = true});
  for (const double d : nn.kernel.D) CHECK(d >= 0);
  CHECK(nn.relativeResidual > 1e-3);
  CHECK(fitKernel(signedRes).relativeResidual < 1e-10);
}

TEST_CASE("with 1% noise on b the 95% intervals cover the truth in at least 18 of 20 seeds", "[learning]") {
  const Truth t = syntheticTruth(kDelta);
  const LatticeStencil st = makeLatticeStencil(5.0, 5.0, kDelta);
  const std::vector<StaticSample> clean = cosineSamples(kLattice, st, t);
  int coverLambda = 0, coverMu = 0, coverAlpha = 0, coverD = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    std::vector<StaticSample> noisy = clean;
    for (auto& s : noisy) {
      const double sd = 0.01 * rms(s.b);
      for (double& b : s.b) b += sd * normal(rng);
    }
    const std::vector<double> w = unitWeights(clean);
    StaticResidual res(kLattice, st, 3, std::move(noisy), w);
    const KernelFit fit = fitKernel(res);
    REQUIRE(fit.converged);
    coverLambda += std::abs(fit.lambda - t.lambda) <= 1.96 * fit.lambdaError;
    coverMu += std::abs(fit.mu - t.mu) <= 1.96 * fit.muError;
    coverAlpha += std::abs(fit.kernel.alpha - t.kernel.alpha) <= 1.96 * fit.alphaError;
    bool allD = true;
    for (int k = 0; k <= 3; ++k) allD = allD && std::abs(fit.kernel.D[k] - t.kernel.D[k]) <= 1.96 * fit.DError[k];
    coverD += allD;
  }
  INFO("covered of 20: lambda " << coverLambda << ", mu " << coverMu << ", alpha " << coverAlpha << ", all D_k "
                                << coverD);
  CHECK(coverLambda >= 18);
  CHECK(coverMu >= 18);
  CHECK(coverAlpha >= 18);
  WARN("covered of 20: lambda " << coverLambda << ", mu " << coverMu << ", alpha " << coverAlpha << ", all D_k " << coverD);
}

TEST_CASE("the stability code's limit for a learned kernel matches the Fourier symbol's largest frequency",
          "[learning]") {
  const Truth t = syntheticTruth(kDelta);
  const LatticeStencil st = makeLatticeStencil(5.0, 5.0, kDelta);
  LearnedLpsForceModel model(kLattice, st, t.kernel, t.lambda, t.mu, 1.0);
  const double rho = 2.0;
  peristep::DynamicProblem problem(model, rho);
  const peristep::StabilityEstimate s = peristep::estimateStabilityLimit(problem);
  const Solvability sym = checkSolvability(kLattice, st, t.kernel, t.lambda, t.mu);
  const double exact = 2.0 / std::sqrt(sym.maxEigen / rho);
  INFO("Lanczos " << s.criticalStep << " (" << s.iterations << " iterations), symbol " << exact);
  // The estimate errs on the safe side (shorter step), by little.
  CHECK(s.criticalStep <= exact * (1 + 1e-9));
  CHECK(s.criticalStep > 0.95 * exact);
  // The tangent is the operator itself: symmetric for a symmetric stencil.
  const Eigen::SparseMatrix<double> T = model.tangent(nullptr);
  CHECK((Eigen::MatrixXd(T) - Eigen::MatrixXd(T).transpose()).cwiseAbs().maxCoeff() < 1e-12 * T.coeffs().cwiseAbs().maxCoeff());
}
