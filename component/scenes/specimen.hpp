#pragma once
// The importer's specimen (scene Specimen): a plate on the vertex grid of GridSpec (h = Lx/(nx-1), points
// on the edges) with a material per domain point, pre-crack segments at any angle and a grip per side,
// broken quasi-statically by the LPS fracture driver (000 Sec. 3.3).
#include <array>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "geometry/segments.hpp"

namespace peristep {

enum class Side { Left = 0, Right = 1, Bottom = 2, Top = 3 };
inline constexpr std::array<const char*, 4> kSideNames{"left", "right", "bottom", "top"};

// A held side's collar moves rigidly by load * (ux, uy); a free side has no collar (traction-free).
struct Grip {
  bool held = false;
  double ux = 0, uy = 0;  // [m] at load 1
};

struct SpecimenSpec {
  // Per domain point, image order [ny][nx]. youngsModulus 0 marks Void: no material (a hole, a cut-out).
  std::vector<double> youngsModulus, poissonRatio, fractureEnergy;  // [Pa], -, [J/m^2]
  std::vector<Segment> cracks;  // pre-cracks: bonds crossing one are broken from the start
  std::array<Grip, 4> grips{};  // by Side
  // Young's modulus times the Karhunen-Loeve factor of mean 1 from the scene's xi, covariance, correlation
  // length, standard deviation and transform (scenes/kl_material.hpp); Void stays Void.
  bool randomField = false;
};

// Throws InvalidInput naming the first inconsistency: a map of the wrong length, a negative or non-finite
// modulus, a fracture energy <= 0, nu outside (-1, 0.5), a segment with an end outside the plate, a held
// grip along a side where the map is Void, a horizon larger than the plate, no held grip.
void validate(const SpecimenSpec& s, const GridSpec& grid);

}  // namespace peristep
