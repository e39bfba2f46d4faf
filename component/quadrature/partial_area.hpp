#pragma once
// Partial-area quadrature weights of the finite-difference scheme, 001:(103).

namespace peristep {

// Exact area of the axis-aligned rectangle [x0, x1] x [y0, y1] that lies inside the disk of the given
// radius centred at the origin.
double rectangleDiskOverlap(double x0, double x1, double y0, double y1, double radius);

// 001:(103): Vbar_ij, the fraction of the square cell of side h centred at x_j (offset (dx, dy) from
// x_i) that lies inside the horizon ball of radius eps about x_i.
double partialAreaFraction(double dx, double dy, double h, double eps);

}  // namespace peristep
