#pragma once
// Per-bond constants of the finite-difference discretization of 001 Sec. 4 and 6 (node-centred square
// cells of side h, partial-area quadrature 001:(103)), precomputed once per geometry.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "geometry/segments.hpp"

namespace peristep {

struct StateBasedBondOptions {
  double horizon = 0;                // eps [m]
  std::vector<double> omega;         // boundary function 001:(2)-(4) per point; empty: 1 everywhere
  std::vector<double> stiffness;     // per-point modulus factor kappa (heterogeneous plates); empty: 1
  std::vector<Segment> cuts;         // pre-cracks: bonds crossing them are left out (kept in preCrack)
};

// Structure of arrays, CSR by point. For bond (i, j) with xi = x_j - x_i, L = |xi|, e = xi/L:
//   q  = e/sqrt(L), so that r = sqrt(L) S = (u_j - u_i) . q   (the argument of f, 001:(3))
//   w  = kappa_ij omega_j J(L/eps) V_j Vbar_ij      (tensile weight; kappa_ij harmonic mean of kappa)
//   ws = omega_j J(L/eps) V_j Vbar_ij sqrt(L)       (hydrostatic weight, 001:(2), (15))
// The unit vector, |xi|, J and the partial-area weight enter the force only through these products.
// q depends on the bond's offset only: a lattice has a few hundred to a few thousand distinct q (bit
// for bit), kept once in a table that stays in cache, and each bond holds its index. So a bond update of
// the tensile force streams 16 bytes (neighbour, direction, w). Bonds with J = 0 (L >= eps) carry no
// force and are not stored.
struct BondList {
  std::vector<std::size_t> offset;      // size points + 1
  std::vector<std::uint32_t> neighbour;
  std::vector<std::uint32_t> direction; // q of the bond: (q[2 d], q[2 d + 1])
  std::vector<double> q, w;
  std::size_t padding = 0;              // stored bonds that are not pairs (see kBondLanes)

  std::size_t bonds() const { return neighbour.size() - padding; }
  double qx(std::size_t k) const { return q[2 * direction[k]]; }
  double qy(std::size_t k) const { return q[2 * direction[k] + 1]; }
};

// The force kernels take the bonds of a point in groups of this many (one AVX-512 register), so each
// point's list is padded to a multiple of it with bonds to itself that carry nothing (q = w = ws = 0):
// no scalar remainder loop, which at eps = 4h cost about as much as the vector part
// (docs/decisions/0014-vectorized-bond-loops.md).
inline constexpr std::size_t kBondLanes = 8;

struct StateBasedBonds : BondList {
  double horizon = 0, cellArea = 0;
  std::vector<double> ws;
  std::vector<double> omega, kappa;     // per point
  // The pairs a pre-crack cuts (no force). Only the diagnostics that count the pre-crack as broken
  // bonds read them (StateBasedModel::damage and tensileEnergyDensity with PreCrack::counted).
  BondList preCrack;

  std::size_t points() const { return offset.size() - 1; }
};

// The cloud must be a lattice of spacing cloud.h (the cell of each node is the h x h square around it);
// its Void points get no bonds.
// Throws InvalidInput for a horizon below h or per-point arrays of the wrong size or range.
StateBasedBonds buildStateBasedBonds(const PointCloud& cloud, const StateBasedBondOptions& options);

}  // namespace peristep
