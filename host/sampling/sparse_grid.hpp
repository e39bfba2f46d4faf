#pragma once
// Smolyak sparse grids by the combination technique (000:(3.8)-(3.9)).
#include <span>

#include "rule1d.hpp"
#include "sample_set.hpp"

namespace peristep::sampling {

enum class Family { Gauss, Nested };

// The 1D rule at 1D level l: Gauss -> gaussRule(law, 2l+1); Nested -> nestedRule(law, l).
// Both start {0}, then the 3-point Gauss rule, and level l is exact for degree >= 2l+1.
Rule1D sparseGridRule(Law law, int level, Family family);

// Level L (0-based; 000 calls it eta = zeta - N) in N = laws.size() dimensions:
//   A(L, N) = sum_{L-N+1 <= |i| <= L, i >= 0} (-1)^{L-|i|} C(N-1, L-|i|) (U^{i_1} x ... x U^{i_N}),
// 000:(3.8) shifted to levels starting at 0. The points are the union (3.9): coincident nodes are
// merged and their weights summed; no node is dropped, even when its weight cancels. Exact for every
// polynomial of total degree <= 2L+1. Level 0 is the single point 0; level 1 has 2N+1 points.
// Points in order of first appearance (multi-indices in lexicographic order), so the order is fixed.
// std::invalid_argument for a negative level or a nested level beyond nestedMaxLevel.
SampleSet smolyakGrid(std::span<const Law> laws, int level, Family family = Family::Gauss);

// Polynomial degree integrated exactly by sparseGridRule(law, level, family).
int sparseGridRuleDegree(Law law, int level, Family family);

// Sparse pseudo-spectral projection (Constantine, Eldred, Phipps 2012, "Sparse pseudospectral
// approximation method"): the combination technique of smolyakGrid applied to tensor pseudo-spectral
// projections instead of tensor quadratures,
//   f ~ sum_a c_a Psi_a,  c_a = sum_i coef_i sum_{x in tensor rule i} w(x) f(x) Psi_a(x),
// Psi_a = prod_d p_{a_d} the orthonormal Hermite/Legendre products. Tensor rule i keeps only the a it
// integrates Psi_a Psi_b exactly for, a_d <= degree(i_d)/2, so each tensor projection is a true
// projection (CEP 2012 Sec. 3); their combination, unlike the combined quadrature of f^2, yields
// Var[f] ~ sum_{a != 0} c_a^2 >= 0. c_0 is the Smolyak quadrature of f.
// The linear map samples -> coefficients, terms sorted by (coefficient, sample); the samples are
// indexed as in smolyakGrid(laws, level, family). Coefficient 0 is a = 0.
struct SpectralTerm {
  std::size_t coefficient, sample;
  double factor;
};
struct SparseProjection {
  std::size_t coefficients = 0;
  std::vector<SpectralTerm> terms;
};
SparseProjection sparsePseudoSpectral(std::span<const Law> laws, int level, Family family = Family::Gauss);

}  // namespace peristep::sampling
