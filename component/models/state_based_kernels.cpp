#include "models/state_based_kernels.hpp"

#include "models/fast_exp.hpp"

#define PERISTEP_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

namespace peristep::kernels {

namespace {

PERISTEP_CLONES
void tensileOnly(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* u, double* f) {
  for (std::size_t i = i0; i < i1; ++i) {
    const double ux = u[2 * i], uy = u[2 * i + 1];
    double fx = 0, fy = 0;
#pragma omp simd reduction(+ : fx, fy)
    for (std::size_t k = a.offset[i]; k < a.offset[i + 1]; ++k) {
      const std::size_t j = a.neighbour[k];
      const double r = (u[2 * j] - ux) * a.qx[k] + (u[2 * j + 1] - uy) * a.qy[k];
      const double t = a.w[k] * r * expNonPositive(-a.beta * r * r);
      fx += t * a.qx[k];
      fy += t * a.qy[k];
    }
    f[2 * i] = a.omega[i] * a.tensileScale * fx;
    f[2 * i + 1] = a.omega[i] * a.tensileScale * fy;
  }
}

PERISTEP_CLONES
void tensileAndHydrostatic(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* u, double* f) {
  for (std::size_t i = i0; i < i1; ++i) {
    const double ux = u[2 * i], uy = u[2 * i + 1], gi = a.kg1[i];
    double fx = 0, fy = 0, hx = 0, hy = 0;
#pragma omp simd reduction(+ : fx, fy, hx, hy)
    for (std::size_t k = a.offset[i]; k < a.offset[i + 1]; ++k) {
      const std::size_t j = a.neighbour[k];
      const double r = (u[2 * j] - ux) * a.qx[k] + (u[2 * j + 1] - uy) * a.qy[k];
      const double t = a.w[k] * r * expNonPositive(-a.beta * r * r);
      const double s = a.ws[k] * (gi + a.kg1[j]);
      fx += t * a.qx[k];
      fy += t * a.qy[k];
      hx += s * a.qx[k];
      hy += s * a.qy[k];
    }
    f[2 * i] = a.omega[i] * (a.tensileScale * fx + a.hydroScale * hx);
    f[2 * i + 1] = a.omega[i] * (a.tensileScale * fy + a.hydroScale * hy);
  }
}

}  // namespace

void stateBasedForce(const ForceArgs& a, std::size_t i0, std::size_t i1, const double* u, double* f) {
  if (a.kg1)
    tensileAndHydrostatic(a, i0, i1, u, f);
  else
    tensileOnly(a, i0, i1, u, f);
}

}  // namespace peristep::kernels
