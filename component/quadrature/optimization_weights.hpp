#pragma once
// Optimization-based meshfree quadrature weights, 000:(3.3)-(3.4).
#include <array>
#include <cstddef>
#include <vector>

#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"

namespace peristep {

// The reproducing space V = {p(z)/|z|^3 : p in P5, integrable on the disk}: in 2D only monomials
// z1^a z2^b of total degree 2..5 qualify, 18 functions.
struct Monomial {
  int a, b;
};
inline constexpr std::size_t kMomentCount = 18;
const std::array<Monomial, kMomentCount>& momentMonomials();

// int_{B_delta} z1^a z2^b / |z|^3 dz = delta^(a+b-1)/(a+b-1) * int_0^{2pi} cos^a t sin^b t dt.
double exactMoment(Monomial m, double delta);

// Weights w_{j,p} for every bond of the rows p with active[p] != 0 (zero on the other rows), aligned
// with nb.index. Each row minimizes sum_j w_j^2 subject to exactness on V, solved as the minimum-norm
// solution w = A^T (A A^T)^+ b by a complete orthogonal decomposition (A may be rank deficient).
// Neighbourhoods of the same shape (a lattice) are solved once and shared.
std::vector<double> optimizationWeights(const PointCloud& cloud, const Neighbours& nb,
                                        const std::vector<char>& active);

// Largest constraint error of row p (in coordinates scaled by delta), relative to the largest
// exact moment: 0 for exact weights.
double constraintError(const PointCloud& cloud, const Neighbours& nb, const std::vector<double>& w,
                       std::size_t p);

}  // namespace peristep
