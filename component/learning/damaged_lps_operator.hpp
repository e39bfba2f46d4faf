#pragma once
// The learned LPS operator with smoothed damage, L_KN of 003:(30)-(33), on a (non-periodic) lattice: bond
// state gamma 003:(28) from the largest stretch a bond has had, corrected dilatation (31) with the tensor (32)
// (pseudo-inverse when singular), normal (33) and the free-surface terms of (30). Bonds to points outside
// the lattice count as broken: the lattice edge is a free surface.
#include <cstddef>
#include <vector>

#include "learning/bernstein_kernel.hpp"
#include "learning/coarse_graining.hpp"
#include "learning/lattice_stencil.hpp"

namespace peristep::learning {

class DamagedLpsOperator {
 public:
  DamagedLpsOperator(CoarseGrid grid, LatticeStencil stencil, const BernsteinKernel& kernel, double lambda, double mu,
                     double eta = 0.05);
  // L_KN[u] at every point; maxStretch[p S + s] is the largest stretch bond s of point p has had.
  std::vector<double> apply(const std::vector<double>& u, const std::vector<double>& maxStretch, double s0) const;
  // Stretch of every bond (003:(23)) in u, combined into `maxStretch` by a running maximum.
  void updateMaxStretch(const std::vector<double>& u, std::vector<double>& maxStretch) const;
  // Largest stretches to start from: +infinity (broken for every s0) on the bonds that cross the segment
  // (ax, ay)-(bx, by), a pre-existing slit; -infinity elsewhere.
  std::vector<double> slit(double ax, double ay, double bx, double by) const;
  // Damage 003:(46) at every point: 1 - (sum of gamma over its bonds inside the lattice) / (their number).
  std::vector<double> damage(const std::vector<double>& maxStretch, double s0) const;
  const CoarseGrid& grid() const { return grid_; }
  // Off: without the free-surface sums of 003:(30) (its last three), for comparison.
  void setFreeSurfaceTerms(bool on) { freeSurface_ = on; }
  // Off: theta of 003:(15) with the full neighbourhood's m (the shape tensor (32) taken as the identity, which it
  // is for a full neighbourhood on a square lattice). Without the free-surface sums the operator is then the
  // gradient of a pointwise energy, a (lambda - mu) theta^2 + b mu sum gamma K W (xi . eta)^2 / |xi|^2, which by
  // Cauchy-Schwarz (K >= 0) stays nonnegative at any damage when it is for an intact isotropic stretch
  // (lambda + mu >= 0). The corrected theta (31) does not shrink with the bonds, and with lambda < mu its
  // negative term can outweigh them (tests/learning_damaged_stability_test.cpp).
  void setCorrectedDilatation(bool on) { corrected_ = on; }

 private:
  std::vector<double> bondStates(const std::vector<double>& maxStretch, double s0) const;  // 003:(28)

  CoarseGrid grid_;
  LatticeStencil stencil_;
  double lambda_, mu_, eta_;
  bool freeSurface_ = true, corrected_ = true;
  std::vector<double> KW_;                 // K(r_s) W_s
  double m_ = 0;                           // m_i of a full neighbourhood, 003 below (18)
  std::vector<std::ptrdiff_t> neighbour_;  // [p S + s], -1 outside the lattice
};

}  // namespace peristep::learning
