#pragma once
// exp(y) for y <= 0 in plain arithmetic, so that the compiler can vectorize the bond loops that
// evaluate f'(r) = 2 c beta r exp(-beta r^2) (a call to the libm exp blocks vectorization).
// Accuracy: a few ulp (relative error below 1e-15) on [-708, 0]; below -708 it returns exp(-708).
#include <bit>
#include <cstdint>
#include <type_traits>

namespace peristep {

// T is double or a GCC vector of doubles (the bond kernels' groups of lanes, state_based_kernels.cpp):
// the same operations lane by lane.
template <class T>
using ExpBits = std::conditional_t<std::is_floating_point_v<T>, std::int64_t, decltype(T{} < T{})>;

template <class T>
inline T expNonPositive(T y) {
  const T zero{};
  y = y < zero - 708.0 ? zero - 708.0 : y;
  constexpr double log2e = 1.4426950408889634;
  constexpr double ln2hi = 0.6931471805598903, ln2lo = 5.497923018708371e-14;  // ln 2 split in two
  constexpr double shift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
  // y = n ln 2 + r with |r| <= ln2/2; exp(r) by its Taylor polynomial of degree 12 (error < 2e-16),
  // evaluated by Estrin's scheme: a dependency chain of 5 operations instead of Horner's 12, which in
  // the bond loops (a latency-bound chain per group of bonds) is what the time goes to.
  const T z = y * log2e + shift;
  const T n = z - shift;
  const T r = (y - n * ln2hi) - n * ln2lo;
  // exp(r) = 1 + r Q(r), Q(r) = sum_{i=0}^{11} r^i / (i+1)!: coefficients paired, then by r^2, r^4, r^8.
  const T r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  const T e0 = r * 0.5 + 1.0, e1 = r * (1.0 / 24.0) + 1.0 / 6.0, e2 = r * (1.0 / 720.0) + 1.0 / 120.0;
  const T e3 = r * (1.0 / 40320.0) + 1.0 / 5040.0, e4 = r * (1.0 / 3628800.0) + 1.0 / 362880.0;
  const T e5 = r * (1.0 / 479001600.0) + 1.0 / 39916800.0;
  const T f0 = e1 * r2 + e0, f1 = e3 * r2 + e2, f2 = e5 * r2 + e4;
  const T q = (f1 * r4 + f0) + f2 * r8;
  const T p = q * r + 1.0;
  // 2^n from the integer held in the low mantissa bits of z (n >= -1022 here, so 2^n is normal).
  using Bits = ExpBits<T>;
  const Bits k = std::bit_cast<Bits>(z) - std::bit_cast<std::int64_t>(shift);
  return p * std::bit_cast<T>(static_cast<Bits>((k + 1023) << 52));
}

}  // namespace peristep
