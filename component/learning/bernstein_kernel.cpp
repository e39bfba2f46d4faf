#include "learning/bernstein_kernel.hpp"

#include <cmath>
#include <numbers>

namespace peristep::learning {

namespace {
// C(n, k) = 1 / ((n + 1) B(k + 1, n - k + 1)).
double binomial(int n, int k) { return 1.0 / ((n + 1) * std::beta(k + 1.0, n - k + 1.0)); }
}  // namespace

double bernstein(int k, int P, double s) {
  return binomial(P, k) * std::pow(s, k) * std::pow(1.0 - s, P - k);
}

double BernsteinKernel::basis(int k, double r) const {
  return std::pow(r, -alpha) * bernstein(k, order(), r / delta);
}

double BernsteinKernel::operator()(double r) const {
  double K = 0.0;
  for (int k = 0; k <= order(); ++k) K += D[static_cast<std::size_t>(k)] * basis(k, r);
  return K;
}

double BernsteinKernel::weightedVolumeCoefficient(int k) const {
  // int_0^delta r^(3-alpha) B_k(r/delta) dr = delta^(4-alpha) C(P,k) Beta(k+4-alpha, P-k+1).
  const int P = order();
  return 2.0 * std::numbers::pi * std::pow(delta, 4.0 - alpha) * binomial(P, k) *
         std::beta(k + 4.0 - alpha, static_cast<double>(P - k + 1));
}

double BernsteinKernel::weightedVolume() const {
  double m = 0.0;
  for (int k = 0; k <= order(); ++k) m += D[static_cast<std::size_t>(k)] * weightedVolumeCoefficient(k);
  return m;
}

}  // namespace peristep::learning
