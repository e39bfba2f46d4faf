#pragma once
// The specimen both the C ABI test and the host test run: a 2 x 1 m plate on the vertex grid (41 x 21
// points, h = 0.05 m, delta = 3h), a notch from the left edge at (-1, -0.1) rising to (-0.6, 0.1), matrix
// E = 1 GPa, G = 1 J/m^2, and an inclusion ten times as stiff and as tough, radius 0.2 m, centred ahead of
// the notch at (0, 0.1). Left and right free, bottom held, top pulled up by loadFactor * 1e-5 m.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace notched_plate {

constexpr std::uint64_t kNx = 41, kNy = 21;
constexpr std::size_t kPoints = kNx * kNy;
constexpr double kLx = 2.0, kLy = 1.0, kH = kLx / (kNx - 1);
constexpr double kXc = 0.0, kYc = 0.1, kR = 0.2;
constexpr double kNotch[4] = {-1.0, -0.1, -0.6, 0.1};  // x0, y0, x1, y1
constexpr double kTopPull = 1e-5;                       // [m] at loadFactor 1
constexpr double kCracked = 0.3;                        // damage of a point the crack has passed
constexpr double kPassed = kXc + kR + 2 * 3 * kH;       // a crack front this far has passed the inclusion

inline double xOf(std::size_t i) { return -0.5 * kLx + kH * static_cast<double>(i % kNx); }
inline double yOf(std::size_t i) { return -0.5 * kLy + kH * static_cast<double>(i / kNx); }
inline bool inInclusion(std::size_t i) { return std::hypot(xOf(i) - kXc, yOf(i) - kYc) <= kR; }

inline std::vector<double> materialMap(bool inclusion, double matrix, double stiff) {
  std::vector<double> m(kPoints, matrix);
  for (std::size_t i = 0; inclusion && i < kPoints; ++i)
    if (inInclusion(i)) m[i] = stiff;
  return m;
}
inline std::vector<double> youngsModulus(bool inclusion) { return materialMap(inclusion, 1e9, 1e10); }
inline std::vector<double> fractureEnergy(bool inclusion) { return materialMap(inclusion, 1.0, 10.0); }

// The largest x of a cracked point (the left edge when none is).
inline double crackFront(const std::vector<double>& damage) {
  double far = -0.5 * kLx;
  for (std::size_t i = 0; i < damage.size(); ++i)
    if (damage[i] > kCracked) far = std::max(far, xOf(i));
  return far;
}

inline std::size_t crackedInInclusion(const std::vector<double>& damage) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < damage.size(); ++i) n += inInclusion(i) && damage[i] > kCracked;
  return n;
}

}  // namespace notched_plate
