#pragma once
// FNV-1a 64 over a byte range. Each step h = (h ^ b) * p is a bijection of h (xor, then a product
// with an odd prime modulo 2^64), so two inputs of equal length that differ in one byte always hash
// differently: every single-byte corruption of a serialized FMU state is detected.
#include <cstdint>
#include <span>

namespace peristep {

inline std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::uint8_t b : bytes) {
    h ^= b;
    h *= 0x100000001b3ull;
  }
  return h;
}

}  // namespace peristep
