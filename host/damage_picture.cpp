#include "damage_picture.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "host_errors.hpp"

namespace peristep::host {

namespace {

Rgb blend(const Rgb& a, const Rgb& b, double t) {
  const auto mix = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + t * (static_cast<double>(y) - x)));
  };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

}  // namespace

bool hasTwoPhases(const std::vector<double>& youngsModulus) {
  if (youngsModulus.empty()) return false;
  const auto [lo, hi] = std::minmax_element(youngsModulus.begin(), youngsModulus.end());
  return *hi - *lo > 1e-9 * std::max(std::abs(*hi), std::abs(*lo));
}

RgbImage damagePicture(std::uint64_t ny, std::uint64_t nx, const std::vector<double>& damage,
                       const std::vector<double>& youngsModulus) {
  const std::size_t n = ny * nx;
  if (damage.size() != n || (!youngsModulus.empty() && youngsModulus.size() != n))
    throw RunError("damage picture: the fields do not have " + std::to_string(ny) + " x " + std::to_string(nx) + " values");
  RgbImage image{ny, nx, std::vector<Rgb>(n, kUniformPhase)};

  if (hasTwoPhases(youngsModulus)) {
    const auto [lo, hi] = std::minmax_element(youngsModulus.begin(), youngsModulus.end());
    const double mid = 0.5 * (*lo + *hi);
    for (std::size_t i = 0; i < n; ++i) image.pixels[i] = youngsModulus[i] > mid ? kStiffPhase : kSoftPhase;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!(damage[i] >= kCrackDamage)) continue;
    const double t = (std::min(damage[i], 1.0) - kCrackDamage) / (1.0 - kCrackDamage);
    image.pixels[i] = blend(kCrackOnset, kCrackFull, t);
  }
  return image;
}

}  // namespace peristep::host
