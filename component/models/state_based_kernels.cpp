#include "models/state_based_kernels.hpp"

#include "models/fast_exp.hpp"

#define PERISTEP_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

namespace peristep::kernels {

namespace {

// The bond arrays as restrict-qualified locals: read through ForceArgs inside the loop, every load
// of a member pointer may alias the stores to f, and GCC then leaves the bond loop scalar ("no vectype
// for stmt ... a->neighbour", "control flow in loop").
struct Bonds {
  const std::size_t* __restrict offset;
  const std::uint32_t* __restrict neighbour;
  const double* __restrict qx;
  const double* __restrict qy;
  const double* __restrict w;
  const double* __restrict ws;
  explicit Bonds(const ForceArgs& a)
      : offset(a.offset), neighbour(a.neighbour), qx(a.qx), qy(a.qy), w(a.w), ws(a.ws) {}
};

PERISTEP_CLONES
void tensileOnly(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* __restrict u,
                 double* __restrict f) {
  const Bonds b(a);
  const double beta = a.beta;
  for (std::size_t i = i0; i < i1; ++i) {
    const double ux = u[2 * i], uy = u[2 * i + 1];
    const std::size_t k0 = b.offset[i], k1 = b.offset[i + 1];
    double fx = 0, fy = 0;
#pragma omp simd reduction(+ : fx, fy)
    for (std::size_t k = k0; k < k1; ++k) {
      const std::size_t j = b.neighbour[k];
      const double r = (u[2 * j] - ux) * b.qx[k] + (u[2 * j + 1] - uy) * b.qy[k];
      const double t = b.w[k] * r * expNonPositive(-beta * r * r);
      fx += t * b.qx[k];
      fy += t * b.qy[k];
    }
    f[2 * i] = a.omega[i] * a.tensileScale * fx;
    f[2 * i + 1] = a.omega[i] * a.tensileScale * fy;
  }
}

PERISTEP_CLONES
void tensileAndHydrostatic(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* __restrict u,
                           double* __restrict f) {
  const Bonds b(a);
  const double* __restrict kg1 = a.kg1;
  const double beta = a.beta;
  for (std::size_t i = i0; i < i1; ++i) {
    const double ux = u[2 * i], uy = u[2 * i + 1], gi = kg1[i];
    const std::size_t k0 = b.offset[i], k1 = b.offset[i + 1];
    double fx = 0, fy = 0, hx = 0, hy = 0;
#pragma omp simd reduction(+ : fx, fy, hx, hy)
    for (std::size_t k = k0; k < k1; ++k) {
      const std::size_t j = b.neighbour[k];
      const double r = (u[2 * j] - ux) * b.qx[k] + (u[2 * j + 1] - uy) * b.qy[k];
      const double t = b.w[k] * r * expNonPositive(-beta * r * r);
      const double s = b.ws[k] * (gi + kg1[j]);
      fx += t * b.qx[k];
      fy += t * b.qy[k];
      hx += s * b.qx[k];
      hy += s * b.qy[k];
    }
    f[2 * i] = a.omega[i] * (a.tensileScale * fx + a.hydroScale * hx);
    f[2 * i + 1] = a.omega[i] * (a.tensileScale * fy + a.hydroScale * hy);
  }
}

PERISTEP_CLONES
void strain(const ForceArgs& a, double scale, std::size_t i0, std::size_t i1, const double* __restrict u,
            double* __restrict theta) {
  const Bonds b(a);
  for (std::size_t i = i0; i < i1; ++i) {
    const double ux = u[2 * i], uy = u[2 * i + 1];
    const std::size_t k0 = b.offset[i], k1 = b.offset[i + 1];
    double t = 0;
#pragma omp simd reduction(+ : t)
    for (std::size_t k = k0; k < k1; ++k) {
      const std::size_t j = b.neighbour[k];
      t += b.ws[k] * ((u[2 * j] - ux) * b.qx[k] + (u[2 * j + 1] - uy) * b.qy[k]);
    }
    theta[i] = scale * t;
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
