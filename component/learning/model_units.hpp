#pragma once
// The learning model's units: eV, A, amu; time in sqrt(amu A^2 / eV).
namespace peristep::learning {

inline constexpr double kTPaPerEvA3 = 0.1602176634;  // 1 eV/A^3 = 160.2 GPa
inline constexpr double kTimeUnit = 1.0180505e-14;    // sqrt(amu A^2 / eV) in s

}  // namespace peristep::learning
