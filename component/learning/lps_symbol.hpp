#pragma once
// Fourier symbol of the learned LPS operator on a lattice: L_K[v e^{i k.x}] = S(k) v e^{i k.x} with
//   S(k) = (lambda - mu) (C1 d / m^2) s s^T + mu (C2 / m) T(k),
//   s = sum_j K W z sin(k.z),  T = sum_j K W z z^T / |z|^2 (1 - cos(k.z))
// (003:(17)-(18) on a symmetric stencil). It gives the solvability check of 003:(37) (S positive definite
// on every non-constant mode), static solutions under cosine loads (003:(43)) and the largest frequency.
#include <array>

#include "learning/bernstein_kernel.hpp"
#include "learning/lattice_stencil.hpp"
#include "learning/lps_residual.hpp"

namespace peristep::learning {

using Symbol = std::array<double, 3>;  // S_xx, S_xy, S_yy

Symbol lpsSymbol(const LatticeStencil& stencil, const BernsteinKernel& kernel, double lambda, double mu, double kx,
                 double ky);

struct Solvability {
  bool moduli = false;       // lambda + mu > 0, mu > 0, alpha < 3
  double minEigen = 0;       // smallest eigenvalue of S over the non-constant modes of the lattice
  double maxEigen = 0;       // largest (omega_max^2 rho)
  bool solvable() const { return moduli && minEigen > 0; }
};
// Over all wave vectors of a periodic nx x ny lattice except k = 0 (the rigid translations).
Solvability checkSolvability(const PeriodicLattice& lattice, const LatticeStencil& stencil,
                             const BernsteinKernel& kernel, double lambda, double mu);

// Static solution of L_K u = b for b = e_c cos(kx x) cos(ky y) at the lattice points x = (i hx, j hy),
// exact for the discrete periodic operator (two plane-wave pairs). kx, ky must be lattice wave numbers.
StaticSample cosineLoadSample(const PeriodicLattice& lattice, const LatticeStencil& stencil,
                              const BernsteinKernel& kernel, double lambda, double mu, double kx, double ky,
                              int component, double amplitude);

}  // namespace peristep::learning
