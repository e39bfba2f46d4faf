#include "random/kl_field.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/fast_exp.hpp"
#include "core/parallel_errors.hpp"
#include "random/randomized_eigen.hpp"

namespace peristep {
namespace {

// Rows of h^2 C handled together: a 64 x N slab of the kernel times the block X is one cache-friendly
// matrix product, and every output row belongs to one slab (so the result does not depend on threads).
constexpr Eigen::Index slabRows = 64;

void validateSpec(std::span<const double> x, std::span<const double> y, double h, const KlSpec& s) {
  require(!x.empty() && x.size() == y.size(), "KL field: x and y must hold the same, non-zero number of points (got " +
                                                  std::to_string(x.size()) + " and " + std::to_string(y.size()) + ")");
  require(std::isfinite(h) && h > 0, "KL field: grid spacing h must be positive");
  require(std::isfinite(s.correlationLength) && s.correlationLength > 0, "KL field: correlation length must be positive");
  require(std::isfinite(s.standardDeviation) && s.standardDeviation > 0,
          "KL field: standard deviation must be positive");
  require(s.modes >= 1 && s.modes <= x.size(), "KL field: number of modes must lie in [1, " + std::to_string(x.size()) +
                                                   "] (the number of points), got " + std::to_string(s.modes));
  for (std::size_t i = 0; i < x.size(); ++i)
    require(std::isfinite(x[i]) && std::isfinite(y[i]), "KL field: point " + std::to_string(i) + " is not finite");
}

}  // namespace

double KlField::covariance(double dx, double dy) const {
  const double s2 = spec_.standardDeviation * spec_.standardDeviation, l = spec_.correlationLength;
  const double r2 = dx * dx + dy * dy;
  return spec_.kind == CovarianceKind::Exponential ? s2 * expNonPositive(-std::sqrt(r2) / l)
                                                   : s2 * expNonPositive(-r2 / (l * l));
}

KlField::KlField(std::span<const double> x, std::span<const double> y, double h, const KlSpec& spec)
    : spec_(spec), x_(x.begin(), x.end()), y_(y.begin(), y.end()), h_(h) {
  validateSpec(x, y, h, spec);
  const auto n = static_cast<Eigen::Index>(x_.size());
  const double area = h * h;
  dense_ = spec.solver == KlSolver::Dense || (spec.solver == KlSolver::Automatic && x_.size() <= spec.denseLimit);

  EigenPairs pairs;
  if (dense_) {
    Eigen::MatrixXd A(n, n);
#pragma omp parallel for schedule(static)
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::Index i = 0; i < n; ++i) A(i, j) = area * covariance(x_[i] - x_[j], y_[i] - y_[j]);
    pairs = denseEigen(A, spec.modes);
  } else {
    // Matrix-free h^2 C X: the kernel is re-evaluated on every product instead of storing N^2 values.
    const BlockProduct apply = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& AX) {
      AX.resize(n, X.cols());
      ParallelErrors errors;  // the slabs allocate
#pragma omp parallel
      {
        Eigen::MatrixXd slab;
#pragma omp for schedule(dynamic)
        for (Eigen::Index r0 = 0; r0 < n; r0 += slabRows)
          errors.capture([&] {
            const Eigen::Index rows = std::min(slabRows, n - r0);
            slab.resize(rows, n);
            for (Eigen::Index j = 0; j < n; ++j)
              for (Eigen::Index i = 0; i < rows; ++i) slab(i, j) = covariance(x_[r0 + i] - x_[j], y_[r0 + i] - y_[j]);
            AX.middleRows(r0, rows).noalias() = area * (slab * X);
          });
      }
      errors.rethrow();
    };
    pairs = randomizedEigen(x_.size(), apply,
                            {spec.modes, spec.oversampling, spec.powerIterations, spec.seed});
  }
  lambda_ = pairs.values.cwiseMax(0.0);  // a PSD operator: tiny negative round-off means zero
  phi_ = pairs.vectors / h;
  variance_ = phi_.array().square().matrix() * lambda_;
}

double KlField::retainedVarianceFraction() const {
  const double s2 = spec_.standardDeviation * spec_.standardDeviation;
  return lambda_.sum() / (s2 * static_cast<double>(x_.size()) * h_ * h_);
}

std::vector<double> KlField::sample(std::span<const double> xi) const {
  require(xi.size() == modes(), "KL field: xi must hold " + std::to_string(modes()) + " values, got " +
                                    std::to_string(xi.size()));
  Eigen::VectorXd scaled(static_cast<Eigen::Index>(xi.size()));
  for (std::size_t k = 0; k < xi.size(); ++k) {
    require(std::isfinite(xi[k]), "KL field: xi[" + std::to_string(k) + "] is not finite");
    scaled[static_cast<Eigen::Index>(k)] = std::sqrt(lambda_[static_cast<Eigen::Index>(k)]) * xi[k];
  }
  const Eigen::VectorXd g = phi_ * scaled;
  return {g.data(), g.data() + g.size()};
}

std::vector<double> KlField::materialField(double E0, std::span<const double> xi, MaterialTransform transform,
                                           std::string_view quantity) const {
  const std::string name(quantity);
  require(std::isfinite(E0) && E0 > 0, "KL field: the mean value " + name + "0 must be positive");
  std::vector<double> E = sample(xi);
  if (transform == MaterialTransform::Positive) {
    for (std::size_t i = 0; i < E.size(); ++i) E[i] = E0 * std::exp(E[i] - 0.5 * variance_[static_cast<Eigen::Index>(i)]);
    return E;
  }
  const auto worst = static_cast<std::size_t>(std::min_element(E.begin(), E.end()) - E.begin());
  const double g = E[worst];
  for (double& e : E) e = E0 * (1.0 + e);
  if (E[worst] <= 0) {
    std::ostringstream msg;
    msg << "random field: " << name << " = " << name << "0 (1 + g) = " << E[worst] << " <= 0 at point (x, y) = ("
        << x_[worst] << ", " << y_[worst] << ") (g = " << g << "); these xi lie too far in the tail for the affine "
        << "field: choose the positive (lognormal) transform, which keeps " << name << " > 0 for every xi";
    throw InvalidInput(msg.str());
  }
  return E;
}

}  // namespace peristep
