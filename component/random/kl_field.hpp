#pragma once
// Karhunen-Loeve expansion of a stationary Gaussian random field on a point set whose points carry
// equal cell areas h^2 (000 Sec. 3.2: the material parameters are a truncated expansion in N i.i.d.
// coordinates xi).
//
//   g(x; xi) = sum_k sqrt(lambda_k) phi_k(x) xi_k,   xi_k ~ N(0, 1)
//
// (lambda_k, phi_k) approximate the eigenpairs of the covariance operator (C phi)(x) = int c(x, y)
// phi(y) dy by the Nystrom discretization h^2 C with C_ij = c(|x_i - x_j|): its eigenvalues approximate
// the continuous ones and phi_k = v_k / h (v_k orthonormal) approximates the L2-normalized function.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "random/kl_options.hpp"

namespace peristep {

enum class KlSolver {
  Automatic,   // dense up to denseLimit points, randomized above
  Dense,       // Eigen's self-adjoint solver on the full N x N matrix
  Randomized,  // randomized subspace iteration with matrix-free products (OpenMP)
};

struct KlSpec {
  CovarianceKind kind = CovarianceKind::Exponential;
  double correlationLength = 0.1;  // l
  double standardDeviation = 0.1;  // s
  std::size_t modes = 10;          // k
  KlSolver solver = KlSolver::Automatic;
  // The dense solver costs ~9 N^3 flops for all N eigenpairs: 1 s of one core at N = 1024, 29 s at
  // N = 2500, where the randomized path takes 0.5 s (docs/decisions/0019-random-field-solvers.md).
  std::size_t denseLimit = 1200;
  std::size_t oversampling = 20;    // randomized path only
  std::size_t powerIterations = 4;  // randomized path only
  std::uint64_t seed = 1;           // of the randomized path's test matrix
};

class KlField {
 public:
  // x, y: point coordinates; h: grid spacing (cell area h^2). Throws InvalidInput for bad input.
  KlField(std::span<const double> x, std::span<const double> y, double h, const KlSpec& spec);

  std::size_t points() const { return x_.size(); }
  std::size_t modes() const { return static_cast<std::size_t>(lambda_.size()); }
  const KlSpec& spec() const { return spec_; }
  // lambda_k, descending (eigenvalues of h^2 C).
  const Eigen::VectorXd& eigenvalues() const { return lambda_; }
  // phi_k at the points, one column per mode (orthonormal columns divided by h).
  const Eigen::MatrixXd& eigenfunctions() const { return phi_; }
  bool usedDenseSolver() const { return dense_; }

  // Sum of the kept eigenvalues over the total variance s^2 * area, area = N h^2 (the trace of h^2 C).
  double retainedVarianceFraction() const;

  // g(x_i; xi) at every point; xi must hold modes() finite values.
  std::vector<double> sample(std::span<const double> xi) const;

  // Material parameter with mean E0 at every point. Affine: throws InvalidInput naming the point with
  // the smallest value when any value is <= 0. Positive: E0 exp(g - v/2) with v(x) = sum lambda_k
  // phi_k(x)^2 the variance of the truncated g at x (-> s^2 as all modes are kept), so that the mean is
  // exactly E0 at every point. `quantity` names the parameter in messages ("E", "G", ...).
  std::vector<double> materialField(double E0, std::span<const double> xi, MaterialTransform transform,
                                    std::string_view quantity = "E") const;

 private:
  double covariance(double dx, double dy) const;

  KlSpec spec_;
  std::vector<double> x_, y_;
  double h_ = 0;
  Eigen::VectorXd lambda_, variance_;  // variance_: v(x_i) of the truncated field
  Eigen::MatrixXd phi_;
  bool dense_ = true;
};

}  // namespace peristep
