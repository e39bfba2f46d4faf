#include "random/weibull_scatter.hpp"

#include <cmath>

namespace peristep {

namespace {
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
}  // namespace

ScatterStream::ScatterStream(std::uint64_t seed, std::uint64_t index) : engine_(splitmix64(splitmix64(seed) ^ index)) {}

double ScatterStream::uniform() { return static_cast<double>((engine_() >> 11) + 1) * 0x1.0p-53; }

double ScatterStream::sign() { return (engine_() >> 63) != 0 ? -1.0 : 1.0; }

double ScatterStream::weibull(double scale, double shape) { return scale * std::pow(-std::log(uniform()), 1.0 / shape); }

double ScatterStream::relativeScatter(const ScatterLaw& law) {
  const double s = sign();
  return s * weibull(law.weibullScale, law.weibullShape) / law.denominator;
}

double ScatterStream::positiveFactor(const ScatterLaw& law) {
  double f;
  do f = 1.0 + relativeScatter(law);
  while (f <= 0);
  return f;
}

}  // namespace peristep
