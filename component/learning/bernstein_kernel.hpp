#pragma once
// The learned influence function of 003:(35)-(36): K(r) = sum_k D_k r^-alpha B_{k,P}(r/delta) on [0, delta].
#include <cstddef>
#include <vector>

namespace peristep::learning {

// B_{k,P}(s) = C(P,k) s^k (1-s)^(P-k), 003:(36).
double bernstein(int k, int P, double s);

struct BernsteinKernel {
  double delta = 1.0;
  double alpha = 1.0;     // singularity order, alpha < 3 (003:(37))
  std::vector<double> D;  // P+1 coefficients

  int order() const { return static_cast<int>(D.size()) - 1; }
  // r^-alpha B_{k,P}(r/delta): the k-th basis function.
  double basis(int k, double r) const;
  double operator()(double r) const;
  // Continuum weighted volume int_{B_delta} K |z|^2 dz (003 below (15)), linear in D.
  double weightedVolume() const;
  // Its coefficient for D_k: 2 pi delta^(4-alpha) C(P,k) B(k+4-alpha, P-k+1).
  double weightedVolumeCoefficient(int k) const;
};

}  // namespace peristep::learning
