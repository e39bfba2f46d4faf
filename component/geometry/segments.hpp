#pragma once
// Line segments that cut bonds: pre-cracks (001 Sec. 6.1, 6.2) are modelled by removing every bond
// whose straight path crosses the crack segment.
#include <vector>

namespace peristep {

struct Segment {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// True when the bond (ax, ay)-(bx, by) crosses the segment. A bond end lying exactly on the segment's
// line counts as lying on its left (seen walking from (x0, y0) to (x1, y1)), so a lattice node sitting
// on the crack line is attached to one face only, never to both.
inline bool bondCrossesSegment(double ax, double ay, double bx, double by, const Segment& s) {
  const auto side = [](double px, double py, double qx, double qy, double rx, double ry) {
    return (qx - px) * (ry - py) - (qy - py) * (rx - px);
  };
  const double da = side(s.x0, s.y0, s.x1, s.y1, ax, ay), db = side(s.x0, s.y0, s.x1, s.y1, bx, by);
  if ((da >= 0) == (db >= 0)) return false;  // both ends on the same side of the crack line
  const double d0 = side(ax, ay, bx, by, s.x0, s.y0), d1 = side(ax, ay, bx, by, s.x1, s.y1);
  return (d0 > 0) != (d1 > 0) || d0 == 0 || d1 == 0;  // the crack's ends straddle (or touch) the bond
}

inline bool bondCrossesAny(double ax, double ay, double bx, double by, const std::vector<Segment>& cuts) {
  for (const Segment& s : cuts)
    if (bondCrossesSegment(ax, ay, bx, by, s)) return true;
  return false;
}

}  // namespace peristep
