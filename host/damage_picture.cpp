#include "damage_picture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

bool isVoid(double youngsModulus) { return !(youngsModulus > 0); }

}  // namespace

PhaseModuli phaseModuli(const std::vector<double>& youngsModulus) {
  PhaseModuli p;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double e : youngsModulus) {
    if (isVoid(e)) {
      ++p.voidPoints;
      continue;
    }
    ++p.points;
    lo = std::min(lo, e), hi = std::max(hi, e);
  }
  if (p.points == 0) return p;
  p.softLo = p.softHi = lo;
  p.two = hi - lo > 1e-9 * hi;
  if (!p.two) {
    p.softHi = hi;
    return p;
  }
  p.mid = 0.5 * (lo + hi);
  p.stiffLo = hi;
  p.stiffHi = hi;
  for (double e : youngsModulus) {
    if (isVoid(e)) continue;
    if (e > p.mid) p.stiffLo = std::min(p.stiffLo, e);
    else p.softHi = std::max(p.softHi, e);
  }
  return p;
}

RgbImage damagePicture(std::uint64_t ny, std::uint64_t nx, const std::vector<double>& damage,
                       const std::vector<double>& youngsModulus) {
  const std::size_t n = ny * nx;
  if (damage.size() != n || (!youngsModulus.empty() && youngsModulus.size() != n))
    throw RunError("damage picture: the fields do not have " + std::to_string(ny) + " x " + std::to_string(nx) + " values");
  RgbImage image{ny, nx, std::vector<Rgb>(n, kUniformPhase)};

  const PhaseModuli phases = phaseModuli(youngsModulus);
  for (std::size_t i = 0; i < youngsModulus.size(); ++i) {
    if (isVoid(youngsModulus[i])) image.pixels[i] = kVoid;
    else if (phases.two) image.pixels[i] = youngsModulus[i] > phases.mid ? kStiffPhase : kSoftPhase;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!(damage[i] >= kCrackDamage) || image.pixels[i] == kVoid) continue;  // a hole is not a crack
    const double t = (std::min(damage[i], 1.0) - kCrackDamage) / (1.0 - kCrackDamage);
    image.pixels[i] = blend(kCrackOnset, kCrackFull, t);
  }
  return image;
}

}  // namespace peristep::host
