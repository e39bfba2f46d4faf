#include "models/state_based_kernels.hpp"

#include "core/fast_exp.hpp"
#include "models/state_based_bonds.hpp"

#define PERISTEP_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

namespace peristep::kernels {

namespace {

// The bond arrays as restrict-qualified locals: read through ForceArgs inside the loop, every load
// of a member pointer may alias the stores to f, and GCC then leaves the bond loop scalar ("no vectype
// for stmt ... a->neighbour", "control flow in loop").
struct Bonds {
  const std::size_t* __restrict offset;
  const std::uint32_t* __restrict neighbour;
  const std::uint32_t* __restrict direction;
  const double* __restrict q;
  const double* __restrict w;
  const double* __restrict ws;
  explicit Bonds(const ForceArgs& a)
      : offset(a.offset), neighbour(a.neighbour), direction(a.direction), q(a.q), w(a.w), ws(a.ws) {}
};

// Each point's bonds come in groups of kBondLanes (state_based_bonds.hpp), one vector of lanes: one
// AVX-512 register, two AVX2 or four SSE2 registers in the clones. Sums are kept per lane and added
// once per point, in the same order in every clone.
using Lanes = double __attribute__((vector_size(kBondLanes * sizeof(double))));
static_assert(kBondLanes == 8, "laneSum adds eight lanes");

inline Lanes load(const double* __restrict p) {
  Lanes v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

// The pairs (base[2 index_l], base[2 index_l + 1]) of a group of bonds as x and y lanes: u_j, or the
// bond's q from the direction table. Each pair is one 16-byte load, regrouped by shuffles (cheaper than
// two gathers of 8 doubles).
struct PairLanes {
  Lanes x, y;
};
inline PairLanes gatherPairs(const double* __restrict base, const std::uint32_t* __restrict index) {
  using Pair = double __attribute__((vector_size(2 * sizeof(double))));
  using Quad = double __attribute__((vector_size(4 * sizeof(double))));
  Pair p[kBondLanes];
  for (std::size_t l = 0; l < kBondLanes; ++l) __builtin_memcpy(&p[l], base + 2 * std::size_t{index[l]}, sizeof(Pair));
  const Quad q0 = __builtin_shufflevector(p[0], p[1], 0, 1, 2, 3), q1 = __builtin_shufflevector(p[2], p[3], 0, 1, 2, 3);
  const Quad q2 = __builtin_shufflevector(p[4], p[5], 0, 1, 2, 3), q3 = __builtin_shufflevector(p[6], p[7], 0, 1, 2, 3);
  const Lanes a = __builtin_shufflevector(q0, q1, 0, 1, 2, 3, 4, 5, 6, 7);
  const Lanes b = __builtin_shufflevector(q2, q3, 0, 1, 2, 3, 4, 5, 6, 7);
  return {__builtin_shufflevector(a, b, 0, 2, 4, 6, 8, 10, 12, 14), __builtin_shufflevector(a, b, 1, 3, 5, 7, 9, 11, 13, 15)};
}

// r = (u_j - u_i) . q of the group of bonds at k, with its q.
struct Stretch {
  Lanes r;
  PairLanes q;
};
inline Stretch stretch(const Bonds& b, std::size_t k, const double* __restrict u, double uix, double uiy) {
  const PairLanes uj = gatherPairs(u, b.neighbour + k), q = gatherPairs(b.q, b.direction + k);
  return {(uj.x - uix) * q.x + (uj.y - uiy) * q.y, q};
}

inline double laneSum(Lanes x) { return ((x[0] + x[4]) + (x[2] + x[6])) + ((x[1] + x[5]) + (x[3] + x[7])); }

PERISTEP_CLONES
void tensileOnly(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* __restrict u,
                 double* __restrict f) {
  const Bonds b(a);
  const double beta = a.beta;
  for (std::size_t i = i0; i < i1; ++i) {
    Lanes fx{}, fy{};
    for (std::size_t k = b.offset[i]; k < b.offset[i + 1]; k += kBondLanes) {
      const auto [r, q] = stretch(b, k, u, u[2 * i], u[2 * i + 1]);
      const Lanes t = load(b.w + k) * r * expNonPositive(-beta * r * r);
      fx += t * q.x;
      fy += t * q.y;
    }
    f[2 * i] = a.omega[i] * a.tensileScale * laneSum(fx);
    f[2 * i + 1] = a.omega[i] * a.tensileScale * laneSum(fy);
  }
}

PERISTEP_CLONES
void tensileAndHydrostatic(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* __restrict u,
                           double* __restrict f) {
  const Bonds b(a);
  const double* __restrict kg1 = a.kg1;
  const double beta = a.beta;
  for (std::size_t i = i0; i < i1; ++i) {
    Lanes fx{}, fy{}, hx{}, hy{};
    for (std::size_t k = b.offset[i]; k < b.offset[i + 1]; k += kBondLanes) {
      const auto [r, q] = stretch(b, k, u, u[2 * i], u[2 * i + 1]);
      const Lanes t = load(b.w + k) * r * expNonPositive(-beta * r * r);
      Lanes g;
      for (std::size_t l = 0; l < kBondLanes; ++l) g[l] = kg1[b.neighbour[k + l]];
      const Lanes s = load(b.ws + k) * (kg1[i] + g);
      fx += t * q.x;
      fy += t * q.y;
      hx += s * q.x;
      hy += s * q.y;
    }
    f[2 * i] = a.omega[i] * (a.tensileScale * laneSum(fx) + a.hydroScale * laneSum(hx));
    f[2 * i + 1] = a.omega[i] * (a.tensileScale * laneSum(fy) + a.hydroScale * laneSum(hy));
  }
}

PERISTEP_CLONES
void strain(const ForceArgs& a, double scale, std::size_t i0, std::size_t i1, const double* __restrict u,
            double* __restrict theta) {
  const Bonds b(a);
  for (std::size_t i = i0; i < i1; ++i) {
    Lanes t{};
    for (std::size_t k = b.offset[i]; k < b.offset[i + 1]; k += kBondLanes)
      t += load(b.ws + k) * stretch(b, k, u, u[2 * i], u[2 * i + 1]).r;
    theta[i] = scale * laneSum(t);
  }
}

}  // namespace

void stateBasedForce(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* u, double* f) {
  if (a.kg1)
    tensileAndHydrostatic(a, i0, i1, u, f);
  else
    tensileOnly(a, i0, i1, u, f);
}

void hydrostaticStrain(const ForceArgs& a, double scale, std::size_t i0, std::size_t i1, const double* u,
                       double* theta) {
  strain(a, scale, i0, i1, u, theta);
}

}  // namespace peristep::kernels
