#pragma once
// The colours of a damage picture: the material (two phases told apart by Young's modulus) in blues,
// Void (no material, Young's modulus 0: holes) in white, and the cracks drawn over the material in
// red to yellow. run_picture draws them with a legend and a colour bar; bench/glass_ceramic writes
// them as a plain PNG (png_writer).
#include <vector>

#include "png_writer.hpp"

namespace peristep::host {

// Damage is the broken fraction of a point's bonds, 000:(3.23). A point on a crack face loses the
// bonds that cross the crack, roughly half of its family (somewhat fewer on coarse grids), while a
// point near but off the crack loses only a few; 0.35 keeps the faces and leaves those out.
inline constexpr double kCrackDamage = 0.35;

inline constexpr Rgb kStiffPhase{150, 200, 245};  // E above the midpoint of the material's range
inline constexpr Rgb kSoftPhase{20, 45, 120};     // E at or below it
inline constexpr Rgb kUniformPhase{60, 110, 190}; // one material (or no modulus to tell phases by)
inline constexpr Rgb kVoid{255, 255, 255};        // no material: the picture's background
inline constexpr Rgb kCrackOnset{190, 30, 0};     // damage == kCrackDamage
inline constexpr Rgb kCrackFull{255, 215, 60};    // damage == 1: brighter with more damage

// The material points (E > 0; Void is not a phase) split into two phases at the midpoint of their
// moduli, or one phase when they hold one material (rounding in the component must not split it).
struct PhaseModuli {
  std::size_t points = 0, voidPoints = 0;
  bool two = false;
  double mid = 0;
  double softLo = 0, softHi = 0;    // range of the one phase, or of the soft one
  double stiffLo = 0, stiffHi = 0;  // range of the stiff phase (two phases only)
};
PhaseModuli phaseModuli(const std::vector<double>& youngsModulus);

// [ny][nx] damage and Young's modulus (empty: the model has none) to one colour per point.
RgbImage damagePicture(std::uint64_t ny, std::uint64_t nx, const std::vector<double>& damage,
                       const std::vector<double>& youngsModulus);

}  // namespace peristep::host
