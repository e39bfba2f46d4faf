#pragma once
// The element loop of the 002 bar's residual over its nonlocal bonds, laid out for SIMD (GamutBarSolver).
//
// Every nonlocal bond of the bar joins a pair of points (p, q) and carries at most two elements (one per
// end point, 002:(24)). The bonds are stored row by row: a row holds the bonds of one kind with one point p
// and the consecutive partners q = qBegin .. qBegin + count - 1, and its elongations are
// e = base(p) + sign * U[q]:
//   inside the bar         e = U[q] - U[p]            (q > p + 1)
//   across x = 0           e = U[p] + U[q]            (the mirror image, u(-x) = -u(x); q >= p)
//   across x = L           e = 2 U[n] - U[p] - U[q]   (u(2L - x) = 2 u(L) - u(x); q >= p)
// U and R are indexed by point (U[0] = 0: the fixed end). The element arrays are structures of arrays,
// one entry per bond, slot A and slot B; a bond with one element, a gap in a row and the padding of a row
// to a multiple of kPairLanes are elements of stiffness 0 and slip elongation +infinity (always elastic,
// no force, no energy), so a row is one branch-free loop whose stores to R[q] do not collide.
//
// An element of stiffness k, slip elongation s (its cap / k) and offset o (the committed slip) at
// stretch x = e - o carries k c with c = clamp(x, -s, s) and stores the energy k c (x - c / 2):
// k x^2 / 2 while elastic, k s (|x| - s / 2) while slipping (002:(35): dU/dt = 0 at the cap).
#include <cstddef>
#include <cstdint>

namespace peristep::gamut {

inline constexpr std::size_t kPairLanes = 8;

enum class PairKind : int { Inside = 0, AcrossStart = 1, AcrossEnd = 2 };

struct PairRow {
  PairKind kind;
  int p;
  int qBegin;
  std::size_t first;  // index of the row's first bond in the element arrays
  std::size_t count;  // a multiple of kPairLanes
};

struct PairElements {
  const double* kA;
  const double* kB;
  const double* sA;
  const double* sB;
  const double* offsetA;
  const double* offsetB;
};

struct PairSums {
  double energy = 0;
  std::size_t slipping = 0;  // bonds with an element at its cap
};

// Adds -dPi/dU of the rows' bonds to R, returns their energy and the bonds slipping. state (if not
// null) receives per bond bit 0: element A elastic, bit 1: element B elastic. lastPoint is n (U[n] = u(L)).
// U and R must hold the points reached by the padding (lastPoint + kPairLanes + 1 entries).
PairSums pairResidual(const PairRow* rows, std::size_t rowCount, const PairElements& el, int lastPoint,
                      const double* U, double* R, std::uint8_t* state);

// The same as a plain scalar loop, bond after bond: the reference the SIMD loop is tested against.
PairSums pairResidualReference(const PairRow* rows, std::size_t rowCount, const PairElements& el, int lastPoint,
                               const double* U, double* R, std::uint8_t* state);

// The commit of a step: every element that slips at U keeps its slip, offset = e - (+-s), the others
// keep their offsets. sA, sB, offsetA, offsetB as in PairElements.
void pairCommit(const PairRow* rows, std::size_t rowCount, const double* sA, const double* sB, double* offsetA,
                double* offsetB, int lastPoint, const double* U);

// Elongation of bond i of a row.
inline double pairElongation(const PairRow& row, int lastPoint, const double* U, std::size_t i) {
  const int q = row.qBegin + static_cast<int>(i);
  switch (row.kind) {
    case PairKind::Inside:
      return -U[row.p] + U[q];
    case PairKind::AcrossStart:
      return U[row.p] + U[q];
    case PairKind::AcrossEnd:
    default:
      return (2 * U[lastPoint] - U[row.p]) - U[q];
  }
}

}  // namespace peristep::gamut
