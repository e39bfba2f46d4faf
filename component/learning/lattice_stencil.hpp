#pragma once
// The bonds of one point of a uniform rectangular lattice (spacing hx, hy) within the horizon delta, with
// the optimization-based quadrature weights of 003:(19) (= 000:(3.3)-(3.4)). On a lattice every point
// with a full neighbourhood has this same stencil, so the learning residuals need it once.
#include <cstddef>
#include <vector>

namespace peristep::learning {

struct LatticeStencil {
  double hx = 0, hy = 0, delta = 0;
  std::vector<int> di, dj;       // lattice offsets of the bonds (the point itself excluded)
  std::vector<double> zx, zy, r;  // bond vectors and lengths
  std::vector<double> W;          // quadrature weights W_{j,i}
  std::vector<std::size_t> opposite;  // the bond -z of bond z
  std::size_t size() const { return W.size(); }
  int reach() const;  // largest |di| or |dj|
};

LatticeStencil makeLatticeStencil(double hx, double hy, double delta);

// Points of a periodic nx x ny lattice, numbered p = i + nx j; neighbour of p across bond s.
struct PeriodicLattice {
  std::size_t nx = 0, ny = 0;
  double hx = 0, hy = 0;
  std::size_t size() const { return nx * ny; }
  std::size_t neighbour(std::size_t p, int di, int dj) const;
};

}  // namespace peristep::learning
