#pragma once
// Coarse-graining of particle data onto a lattice, 003:(4)-(12): cone weights (4), made adaptive near
// cracks by the WENO-like smoothness indicator (5)-(9) so that averages do not reach across a crack.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace peristep::learning {

// 003:(6)-(9): alpha = min over splits of (two-piece linear least-squares error) / (one-line error), the
// data sorted by d and split into two contiguous parts of >= kMinPart points, the jump (midway between the
// parts) in (from, to). Near 1 on smooth data with particle-scale scatter, near 0 across a jump there.
// Too few points, or data a line fits exactly, give 1 (nothing to detect). Parts of 3: a line through two
// points fits them exactly, jump or not.
inline constexpr std::size_t kMinPart = 3;
double smoothnessIndicator(std::span<const double> d, std::span<const double> U, double from = -INFINITY,
                           double to = INFINITY);

struct CoarseGrid {
  std::size_t nx = 0, ny = 0;
  double x0 = 0, y0 = 0, hx = 0, hy = 0;  // point (i, j) at (x0 + i hx, y0 + j hy)
  bool periodic = false;                  // periodic with period (nx hx, ny hy)
  std::size_t size() const { return nx * ny; }
  double x(std::size_t p) const { return x0 + static_cast<double>(p % nx) * hx; }
  double y(std::size_t p) const { return y0 + static_cast<double>(p / nx) * hy; }
};

struct CoarseFields {
  std::vector<double> rho;   // mass per volume, per point (003:(10))
  std::vector<double> u, b;  // interleaved (x, y): displacement (12) and body force per volume (11)
};

// Particles at reference positions (X, Y) with masses; the grid points' neighbourhoods (particles within R,
// minimum image on a periodic grid) and cone weights tau = max(0, R - |X - x|) are found once.
// The indicator of a pair (x, X_e) at distance L uses the particles within R of x that lie within `band` of
// the line through x and X_e (both directions), with the jump in (0, L). 003 takes the particles within R
// that project onto the segment [0, L]; but where the segment crosses a crack obliquely the two sides'
// projections interleave (no split separates them), and the particles just across a crack face are too
// few for a line fit of their own: the jump goes unseen. The whole chord gives both parts enough points.
class CoarseGraining {
 public:
  CoarseGraining(CoarseGrid grid, std::vector<double> X, std::vector<double> Y, std::vector<double> mass,
                 double radius, double thickness, double band = 1.5);
  // U, B interleaved per particle. adaptive: weights tau * alpha (003:(5)); otherwise the cone alone (4).
  CoarseFields average(std::span<const double> U, std::span<const double> B, bool adaptive) const;
  const CoarseGrid& grid() const { return grid_; }

 private:
  struct Link {
    std::size_t particle;
    double dx, dy, tau;  // X - x (minimum image) and the cone weight
  };
  CoarseGrid grid_;
  std::vector<double> X_, Y_, mass_;
  double radius_, thickness_, band_;
  std::vector<std::vector<Link>> links_;  // per grid point
};

}  // namespace peristep::learning
