#include "orthogonal_polynomials.hpp"

#include <cmath>

namespace peristep::sampling::detail {

Real recurrenceCoefficient(Law law, int k) {
  if (k <= 0) return 0;
  const Real kk = k;
  if (law == Law::Normal) return std::sqrt(kk);
  return kk / std::sqrt(4 * kk * kk - 1);
}

PolynomialValue orthonormalPolynomial(Law law, int n, Real x) {
  Real p = 1, pPrev = 0, d = 0, dPrev = 0;
  for (int k = 0; k < n; ++k) {
    const Real s = recurrenceCoefficient(law, k), sNext = recurrenceCoefficient(law, k + 1);
    const Real pNext = (x * p - s * pPrev) / sNext;
    const Real dNext = (x * d + p - s * dPrev) / sNext;
    pPrev = p;
    p = pNext;
    dPrev = d;
    d = dNext;
  }
  return {p, d};
}

Real christoffelWeight(Law law, int n, Real x) {
  Real sum = 0;
  for (const Real p : orthonormalPolynomials(law, n - 1, x)) sum += p * p;
  return 1 / sum;
}

std::vector<Real> orthonormalPolynomials(Law law, int n, Real x) {
  std::vector<Real> p(n + 1);
  p[0] = 1;
  for (int k = 0; k < n; ++k)
    p[k + 1] = (x * p[k] - (k > 0 ? recurrenceCoefficient(law, k) * p[k - 1] : 0)) / recurrenceCoefficient(law, k + 1);
  return p;
}

}  // namespace peristep::sampling::detail
