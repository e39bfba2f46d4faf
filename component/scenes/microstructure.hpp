#pragma once
// Glass-ceramic microstructure (000 Sec. 5): identical elliptical crystals with uniform centres and
// angles, added until the crystal area fraction of the domain reaches f; reproducible from a seed.
#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace peristep {

struct EllipseShape {
  double semiMajor = 12e-6, semiMinor = 7.5e-6;  // 000 Sec. 5: aspect ratio 1.6
};

// Crystal indicator R (000:(5.1)) of every point, collar included. The area fraction is measured on
// the domain points; the last ellipse may overshoot f by at most its own area.
std::vector<std::uint8_t> generateMicrostructure(const PointCloud& cloud, double fraction, std::uint64_t seed,
                                                 EllipseShape shape = {});

// Fraction of domain points in the crystal phase.
double crystalFraction(const PointCloud& cloud, const std::vector<std::uint8_t>& crystal);

}  // namespace peristep
