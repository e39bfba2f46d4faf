#pragma once
// The random perturbation of 002:(26): M = Mbar + sign(randn()) wblrnd(scale, shape) Mbar / denominator,
// drawn independently for every point or bond. With scale 1 and shape 2, E[W^2] = Gamma(2) = 1, so the
// relative perturbation has mean 0 and RMS exactly 1 / denominator. The "KL truncation" 002:(27)
// names no covariance kernel and is not applied (it would change nothing without one).
#include <cstdint>
#include <random>

namespace peristep {

struct ScatterLaw {
  double denominator = 10;  // the /10 of 002:(26)
  double weibullScale = 1;
  double weibullShape = 2;
};

// One realization's stream of draws: mt19937_64 with our own transforms, so that a seed gives the
// same numbers with every standard library.
class ScatterStream {
 public:
  // Realization `index` of the study seeded with `seed` (splitmix64 of both: independent streams).
  ScatterStream(std::uint64_t seed, std::uint64_t index);

  double uniform();  // (0, 1]
  double sign();     // +1 or -1 with probability 1/2 each: sign(randn()) of 002:(26), (36)
  double weibull(double scale, double shape);  // scale (-ln U)^(1/shape)
  // The relative perturbation sign W / denominator of 002:(26).
  double relativeScatter(const ScatterLaw& law);
  // 1 + relativeScatter, drawn again while it is <= 0 (a modulus or weight must stay positive; with
  // shape 2 and /10 that needs W > 10, probability e^-100; with shape 1, e^-10).
  double positiveFactor(const ScatterLaw& law);

 private:
  std::mt19937_64 engine_;
};

}  // namespace peristep
