#pragma once
// Full tensor product of Gauss rules (000:(3.7)): pointsPerDim^N points, exact for every polynomial
// of degree <= 2 pointsPerDim - 1 in each coordinate separately.
#include <span>

#include "rule1d.hpp"
#include "sample_set.hpp"

namespace peristep::sampling {

// One coordinate per law (Gauss-Hermite for Normal, Gauss-Legendre for Uniform); the last coordinate
// varies fastest. std::invalid_argument for pointsPerDim < 1, std::length_error when the grid does
// not fit in memory's address range.
SampleSet tensorGrid(std::span<const Law> laws, int pointsPerDim);

}  // namespace peristep::sampling
