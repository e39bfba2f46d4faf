#pragma once
// Kernel learning step of 003 (Algorithm 1 (iv), loss 003:(40)) by variable projection: for fixed kernel
// parameters the residual is linear in (lambda, mu), which are eliminated by a linear least-squares solve;
// the kernel parameters are found by Levenberg-Marquardt on the projected residual, an LM of our own: against
// Eigen's it used fewer evaluations in six of eight fits and fits 003's kernel form better
// (docs/decisions/0022-own-levenberg-marquardt.md).
//
// Parameters: the kernel enters only through K/m (003:(17)-(18)), so its scale is fixed by int K|z|^2 = 1.
// The fit works with xi_k = D_k c_k (the share of basis k in that integral, sum xi_k = 1, xi_P eliminated)
// and alpha; results are reported as D_k = xi_k / c_k(alpha). With `nonnegative` the fit's parameters are b_k
// with xi_k = b_k^2 / (1 + sum b_j^2) (k < P) and xi_P = 1 / (1 + sum b_j^2): every D_k >= 0, so K >= 0 on
// [0, delta] (the Bernstein basis is nonnegative), and breaking bonds cannot leave negative stiffness behind.
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "learning/bernstein_kernel.hpp"
#include "learning/lps_residual.hpp"

namespace peristep::learning {

struct KernelFitOptions {
  double alpha0 = 1.0;            // start: K = c r^-alpha0 (all xi equal)
  int maxIterations = 200;
  double stepTolerance = 1e-13;   // relative size of the last LM step
  bool nonnegative = false;       // K >= 0: D_k >= 0 by the parametrization above
};

struct KernelFit {
  BernsteinKernel kernel;  // normalized: int K |z|^2 dz = 1
  double lambda = 0, mu = 0;
  // Standard errors (from sigma^2 (J^T J)^-1 of the full residual, delta method for D) of lambda, mu,
  // D_0..D_P and alpha.
  double lambdaError = 0, muError = 0, alphaError = 0;
  std::vector<double> DError;
  double rss = 0;        // weighted sum of squared residuals
  double sigma2 = 0;     // rss / (rows - parameters)
  double relativeResidual = 0;  // sqrt(rss / |weighted b|^2)
  int iterations = 0;
  std::size_t evaluations = 0;  // projected residual evaluations
  bool converged = false;
};

KernelFit fitKernel(StaticResidual& residual, const KernelFitOptions& options = {});

// sqrt(|L_K u - b|^2 / |b|^2) of the weighted samples of `residual` for a given model (validation loss).
double relativeResidual(StaticResidual& residual, const BernsteinKernel& kernel, double lambda, double mu);

}  // namespace peristep::learning
