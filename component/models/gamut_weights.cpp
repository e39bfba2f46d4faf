#include "models/gamut_weights.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep {

double interactionLength(double nearest, double farthest) {
  require(nearest > 0 && farthest > nearest, "gamut weights: needs 0 < nearest < farthest nonlocal distance");
  return std::sqrt((farthest * farthest - nearest * nearest) / (4.0 * std::log(farthest / nearest)));
}

void calibratedWeights(std::span<const double> distances, double sigma, ScatterStream* stream, const ScatterLaw& law,
                       std::span<double> weights) {
  double sum = 0;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    // The 1 / sqrt(2 pi sigma^2) of (22) cancels in the normalization (21).
    double w = std::exp(-distances[i] * distances[i] / (2 * sigma * sigma));
    if (stream) w *= stream->positiveFactor(law);
    weights[i] = w;
    sum += w;
  }
  for (double& w : weights) w /= sum;
}

}  // namespace peristep
