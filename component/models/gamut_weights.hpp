#pragma once
// Calibrated weights of the nonlocal bonds of one point of the 002 bar.
#include <span>

#include "random/weibull_scatter.hpp"

namespace peristep {

// sigma_stdev of 002:(31) from the nearest and the farthest nonlocal point. The "uncalibrated nonlocal
// potentials" are read as those of equal nonlocal springs under a uniform strain, U ~ l^2, so that
// ln(max U / min U) = 2 ln(l_far / l_near) and sigma^2 = (l_far^2 - l_near^2) / (4 ln(l_far / l_near)).
double interactionLength(double nearest, double farthest);

// Weights of the nonlocal points at `distances`: the Gaussian of 002:(22) (the exp(-l^2 / (2 sigma^2))
// of (22), not the misprinted exp(-l / (2 sigma)) of (32)), scattered by 002:(26) when `stream` is not
// null (a factor <= 0 drawn again), normalized to sum 1 (002:(21), (13)).
void calibratedWeights(std::span<const double> distances, double sigma, ScatterStream* stream, const ScatterLaw& law,
                       std::span<double> weights);

}  // namespace peristep
