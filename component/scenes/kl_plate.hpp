#pragma once
// The KL plate (000 Sec. 2.2-3.2) as a preset of the specimen: Young's modulus E0 (1 + g) or
// E0 exp(g - v/2) of a Karhunen-Loeve field over the whole cloud, collar included, E0 = 1 (dimensionless, as
// Tests 1-3); every side held, the collar stretched uniaxially, u = loadFactor (0, 0.01 y); no body force,
// nothing breaks: one factorization per sample, one solve per load step.
#include "scenes/specimen.hpp"

namespace peristep {

// The specimen of the KL plate on `grid` with Poisson ratio nu.
SpecimenSpec klPlatePreset(const GridSpec& grid, double nu);

}  // namespace peristep
