#pragma once
// The hot loops of the state-based model 001:(2), (14)-(15) over a range of points, compiled for
// several instruction sets (chosen at run time: AVX-512, AVX2+FMA or the x86-64 baseline), so that the
// library stays portable while the bond loops use the widest vectors the machine has.
// tests/kernel_vectorization checks that every clone of every loop here holds vector instructions.
#include <cstddef>
#include <cstdint>

namespace peristep::kernels {

struct ForceArgs {
  const std::size_t* offset;
  const std::uint32_t *neighbour, *direction;
  const double *q, *w, *ws, *omega;  // q: (qx, qy) pairs indexed by direction
  double beta, tensileScale, hydroScale;
  const double* kg1;  // kappa g'(theta) per point; null: no hydrostatic force
};

// For i in [i0, i1), with r = (u_j - u_i).q over the bonds of i (in groups of kBondLanes):
//   f_i = omega_i [tensileScale sum w r exp(-beta r^2) q + hydroScale sum ws (kg1_i + kg1_j) q].
void stateBasedForce(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* u, double* f);

// For i in [i0, i1): theta_i = scale sum ws r over the bonds of i (001:(2) with scale = 1/(pi eps^2)).
void hydrostaticStrain(const ForceArgs& a, double scale, std::size_t i0, std::size_t i1, const double* u,
                       double* theta);

}  // namespace peristep::kernels
