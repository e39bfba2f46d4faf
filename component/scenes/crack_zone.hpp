#pragma once
// The crack zone of a dynamic scene (the points of D with Z > 1, 001:(104)) split among its pre-cracks,
// and the shape of each crack's part: how far it has grown and how wide its damaged band is.
#include <cstddef>
#include <vector>

#include "scenes/dynamic_scene.hpp"

namespace peristep {

// For every point, the pre-crack whose zone it belongs to, -1 when none: a breadth-first search over
// lattice neighbours through Z > 1 points, started from those within eps of each crack tip, so a
// damaged point joins the nearest crack zone it is connected to.
std::vector<int> crackZoneOwners(const DynamicScene& scene, const std::vector<double>& Z);

// Coordinates of (x, y) relative to a pre-crack's tip (x1, y1): distance along its direction (advance, > 0
// beyond the tip) and across it (offset, > 0 to its left).
struct CrackCoordinates {
  double advance, offset;
};
CrackCoordinates crackCoordinates(const Segment& s, double x, double y);

// One lattice row of a crack's zone beyond its tip, across the crack's direction.
struct CrackBandRow {
  double advance = 0;              // distance of the row beyond the tip along the crack [m] (of its nearest point)
  double left = 0, right = 0;      // offsets of the outermost Z > 1 points from the crack line [m]
  std::size_t points = 0;
  double width(double h) const { return right - left + h; }  // cells covered, ends included
};

// Per pre-crack, the rows of its zone beyond the tip in order of advance (rows without a point left out).
// A sharp crack is a band a few h wide whose centre stays near the line it grew from, or drifts
// smoothly when it curves.
std::vector<std::vector<CrackBandRow>> crackBands(const DynamicScene& scene, const std::vector<double>& Z);

}  // namespace peristep
