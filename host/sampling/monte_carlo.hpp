#pragma once
// Monte Carlo samples of independent standardized coordinates, reproducible across compilers and
// standard libraries: std::mt19937_64 (its output is fixed by the standard) with our own transforms,
// not std::normal_distribution or std::uniform_real_distribution (their algorithms are not).
#include <cstdint>
#include <span>

#include "rule1d.hpp"
#include "sample_set.hpp"

namespace peristep::sampling {

// count points, weights 1/count. One generator seeded with `seed` is read in order, point by point,
// coordinate by coordinate, so the first k points of a larger set are the k-point set: a sample
// loop can be extended with the same seed. Transforms of the 64-bit draws r:
//   u = (r >> 11) * 2^-53 in [0, 1) (53 random bits, exactly representable);
//   Uniform: 2u - 1 in [-1, 1);
//   Normal: Box-Muller, r = sqrt(-2 ln(1 - u1)), z = r cos(2 pi u2) then r sin(2 pi u2) for the next
//           normal coordinate (1 - u1 lies in (0, 1], so the logarithm is finite).
// The trigonometric and logarithm functions may differ in the last bit between C libraries.
SampleSet monteCarlo(std::span<const Law> laws, std::size_t count, std::uint64_t seed);

}  // namespace peristep::sampling
