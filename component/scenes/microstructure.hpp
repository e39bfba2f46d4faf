#pragma once
// Glass-ceramic microstructure (000 Sec. 5): identical elliptical crystals with uniform centres and
// angles, added until the crystal area fraction of the domain reaches f; reproducible from a seed.
// The crystals live in continuous coordinates and are sampled onto a grid only afterwards, so a seed
// is one material at every grid spacing.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace peristep {

struct EllipseShape {
  double semiMajor = 12e-6, semiMinor = 7.5e-6;  // 000 Sec. 5: aspect ratio 1.6
};

struct Crystal {
  double cx = 0.0, cy = 0.0, angle = 0.0;  // centre in the domain centred at the origin; major axis angle
};

// Cells per semi-minor axis of the raster on which the covered fraction is measured while placing
// (docs/decisions/0021-grid-independent-microstructure.md).
inline constexpr double kCoverRasterPerMinorAxis = 4.0;

// Crystals of a seed on the Lx x Ly domain centred at the origin: drawn until their union covers a
// fraction f of the domain, measured on a raster of cells of semiMinor / kCoverRasterPerMinorAxis
// (fixed by the shape, not by any simulation grid). The last crystal may overshoot f by its own area.
std::vector<Crystal> placeCrystals(double Lx, double Ly, double fraction, std::uint64_t seed, EllipseShape shape = {});

// Crystal indicator R (000:(5.1)) of every point of the cloud, collar included: 1 inside any crystal.
std::vector<std::uint8_t> sampleCrystals(const PointCloud& cloud, std::span<const Crystal> crystals,
                                         EllipseShape shape = {});

// placeCrystals on the cloud's domain, then sampleCrystals; f = 1 marks every point.
std::vector<std::uint8_t> generateMicrostructure(const PointCloud& cloud, double fraction, std::uint64_t seed,
                                                 EllipseShape shape = {});

// Fraction of domain points in the crystal phase.
double crystalFraction(const PointCloud& cloud, const std::vector<std::uint8_t>& crystal);

}  // namespace peristep
