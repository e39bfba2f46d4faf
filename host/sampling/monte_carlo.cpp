#include "monte_carlo.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace peristep::sampling {
namespace {

class StandardStream {
 public:
  explicit StandardStream(std::uint64_t seed) : engine_(seed) {}

  double uniform() { return 2 * unit() - 1; }

  double normal() {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    const double radius = std::sqrt(-2 * std::log(1 - unit()));
    const double angle = 2 * std::numbers::pi * unit();
    spare_ = radius * std::sin(angle);
    hasSpare_ = true;
    return radius * std::cos(angle);
  }

 private:
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  std::mt19937_64 engine_;
  double spare_ = 0;
  bool hasSpare_ = false;
};

}  // namespace

SampleSet monteCarlo(std::span<const Law> laws, std::size_t count, std::uint64_t seed) {
  SampleSet set;
  set.dims = laws.size();
  set.points.reserve(count * laws.size());
  set.weights.assign(count, count > 0 ? 1.0 / static_cast<double>(count) : 0.0);
  StandardStream stream(seed);
  for (std::size_t k = 0; k < count; ++k)
    for (const Law law : laws) set.points.push_back(law == Law::Normal ? stream.normal() : stream.uniform());
  return set;
}

}  // namespace peristep::sampling
