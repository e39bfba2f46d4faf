#include "solvers/gamut_pair_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#define PERISTEP_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

namespace peristep::gamut {

namespace {

// kPairLanes bonds at once: one AVX-512 register, two AVX2 or four SSE2 registers in the clones. Written
// with GCC's vector types: the loop carries two sums (the row's force, the energy) that GCC would not
// vectorize in a plain loop without reassociating them itself.
using Lanes = double __attribute__((vector_size(kPairLanes * sizeof(double))));
using Ints = std::int32_t __attribute__((vector_size(kPairLanes * sizeof(std::int32_t))));
using Bytes = std::uint8_t __attribute__((vector_size(kPairLanes)));
static_assert(kPairLanes == 8, "laneSum adds eight lanes");

[[gnu::always_inline]] inline Lanes load(const double* __restrict p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline void store(double* __restrict p, Lanes v) { std::memcpy(p, &v, sizeof v); }
inline double laneSum(Lanes x) { return ((x[0] + x[4]) + (x[2] + x[6])) + ((x[1] + x[5]) + (x[3] + x[7])); }

struct RowSums {
  double force, energy;
  std::size_t slipping;
};

// One row: e = base + sign u[i]; r[i] -= sign t_i; returns sum t_i, the energy and the bonds slipping.
// The element arrays start at the row's first bond. Branch-free: clamp by blends, the state from masks.
[[gnu::always_inline]] inline RowSums row(double base, double sign, std::size_t count, const double* __restrict kA, const double* __restrict kB,
                   const double* __restrict sA, const double* __restrict sB, const double* __restrict oA,
                   const double* __restrict oB, const double* __restrict u, double* __restrict r,
                   std::uint8_t* __restrict state) {
  Lanes force{}, energy{}, slipping{};
  const Lanes zero{}, one = zero + 1.0, two = zero + 2.0, three = zero + 3.0;
  for (std::size_t i = 0; i < count; i += kPairLanes) {
    const Lanes e = base + sign * load(u + i);
    const Lanes xA = e - load(oA + i), xB = e - load(oB + i);
    const Lanes a = load(sA + i), b = load(sB + i);
    const Lanes cA = xA > a ? a : (xA < -a ? -a : xA);
    const Lanes cB = xB > b ? b : (xB < -b ? -b : xB);
    const Lanes tA = load(kA + i) * cA, tB = load(kB + i) * cB;
    const Lanes t = tA + tB;
    store(r + i, load(r + i) - sign * t);
    force += t;
    energy += tA * (xA - 0.5 * cA) + tB * (xB - 0.5 * cB);
    // Elastic: |x| <= s, i.e. the clamp left x as it was (slot padding: s = +infinity, always elastic).
    // The bits as doubles: selects and adds of doubles stay in vector registers in every clone.
    const Lanes st = (cA == xA ? one : zero) + (cB == xB ? two : zero);
    slipping += st != three ? one : zero;
    if (state) {
      const Bytes bits = __builtin_convertvector(__builtin_convertvector(st, Ints), Bytes);
      std::memcpy(state + i, &bits, sizeof bits);
    }
  }
  return {laneSum(force), laneSum(energy), static_cast<std::size_t>(laneSum(slipping))};
}

// The point p of a row: base of the elongations, the sign of U[q], and what the row's force sum does to R.
inline double rowBase(const PairRow& w, int last, const double* U) {
  return w.kind == PairKind::Inside ? -U[w.p] : w.kind == PairKind::AcrossStart ? U[w.p] : 2 * U[last] - U[w.p];
}
inline double rowSign(const PairRow& w) { return w.kind == PairKind::AcrossEnd ? -1.0 : 1.0; }
inline void closeRow(const PairRow& w, int last, double sum, double* R) {
  switch (w.kind) {
    case PairKind::Inside:  // d e / d U[p] = -1
      R[w.p] += sum;
      break;
    case PairKind::AcrossStart:  // +1
      R[w.p] -= sum;
      break;
    case PairKind::AcrossEnd:  // -1 at p, +2 at n
      R[w.p] += sum;
      R[last] -= 2 * sum;
      break;
  }
}

PERISTEP_CLONES
PairSums simd(const PairRow* rows, std::size_t rowCount, const PairElements& el, int last, const double* U, double* R,
              std::uint8_t* state) {
  PairSums sums;
  for (std::size_t w = 0; w < rowCount; ++w) {
    const PairRow& pr = rows[w];
    const std::size_t f = pr.first;
    const RowSums s = row(rowBase(pr, last, U), rowSign(pr), pr.count, el.kA + f, el.kB + f, el.sA + f, el.sB + f,
                          el.offsetA + f, el.offsetB + f, U + pr.qBegin, R + pr.qBegin, state ? state + f : nullptr);
    closeRow(pr, last, s.force, R);
    sums.energy += s.energy;
    sums.slipping += s.slipping;
  }
  return sums;
}

PERISTEP_CLONES
void commit(const PairRow* rows, std::size_t rowCount, const double* slipA, const double* slipB, double* offsetA,
            double* offsetB, int last, const double* U) {
  for (std::size_t w = 0; w < rowCount; ++w) {
    const PairRow& pr = rows[w];
    const double base = rowBase(pr, last, U), sign = rowSign(pr);
    const double* __restrict u = U + pr.qBegin;
    const double* __restrict sA = slipA + pr.first;
    const double* __restrict sB = slipB + pr.first;
    double* __restrict oA = offsetA + pr.first;
    double* __restrict oB = offsetB + pr.first;
    for (std::size_t i = 0; i < pr.count; i += kPairLanes) {
      const Lanes e = base + sign * load(u + i);
      const Lanes a = load(sA + i), b = load(sB + i), offA = load(oA + i), offB = load(oB + i);
      const Lanes xA = e - offA, xB = e - offB;
      const Lanes cA = xA > a ? a : (xA < -a ? -a : xA);
      const Lanes cB = xB > b ? b : (xB < -b ? -b : xB);
      // Slipping (the clamp moved x): the offset that puts the element at its cap, e - (+-s).
      store(oA + i, cA == xA ? offA : e - cA);
      store(oB + i, cB == xB ? offB : e - cB);
    }
  }
}

}  // namespace

void pairCommit(const PairRow* rows, std::size_t rowCount, const double* sA, const double* sB, double* offsetA,
                double* offsetB, int lastPoint, const double* U) {
  commit(rows, rowCount, sA, sB, offsetA, offsetB, lastPoint, U);
}

PairSums pairResidual(const PairRow* rows, std::size_t rowCount, const PairElements& el, int lastPoint, const double* U,
                      double* R, std::uint8_t* state) {
  return simd(rows, rowCount, el, lastPoint, U, R, state);
}

PairSums pairResidualReference(const PairRow* rows, std::size_t rowCount, const PairElements& el, int lastPoint,
                               const double* U, double* R, std::uint8_t* state) {
  PairSums sums;
  for (std::size_t w = 0; w < rowCount; ++w) {
    const PairRow& pr = rows[w];
    const double sign = rowSign(pr);
    double sum = 0;
    for (std::size_t i = 0; i < pr.count; ++i) {
      const std::size_t j = pr.first + i;
      const double e = pairElongation(pr, lastPoint, U, i);
      double t = 0;
      std::uint8_t bits = 0;
      const double k[2] = {el.kA[j], el.kB[j]}, s[2] = {el.sA[j], el.sB[j]}, x[2] = {e - el.offsetA[j], e - el.offsetB[j]};
      for (int a = 0; a < 2; ++a) {
        const double c = std::clamp(x[a], -s[a], s[a]);
        t += k[a] * c;
        sums.energy += k[a] * c * (x[a] - 0.5 * c);
        if (std::abs(x[a]) <= s[a]) bits |= static_cast<std::uint8_t>(1 << a);
      }
      R[pr.qBegin + static_cast<int>(i)] -= sign * t;
      sum += t;
      sums.slipping += bits != 3;
      if (state) state[j] = bits;
    }
    closeRow(pr, lastPoint, sum, R);
  }
  return sums;
}

}  // namespace peristep::gamut
