#include "models/state_based_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>

#include "core/errors.hpp"
#include "core/flush_denormals.hpp"
#include "models/state_based_kernels.hpp"

namespace peristep {

StateBasedModel::StateBasedModel(const StateBasedMaterial& material, StateBasedBonds bonds)
    : material_(material), bonds_(std::move(bonds)) {
  require(material_.density > 0 && material_.f.c > 0 && material_.f.beta > 0,
          "state-based model: material constants c, beta and the density must be positive");
  require(bonds_.points() > 0 && bonds_.horizon > 0, "state-based model: no bonds were built");
  const double eps = bonds_.horizon, pi = std::numbers::pi;
  hydrostatic_ = material_.g.active();
  parallel_ = bonds_.bonds() >= 100000;
  tensileScale_ = 4.0 * material_.f.c * material_.f.beta / (pi * eps * eps * eps);
  energyScale_ = material_.f.c / (pi * eps * eps * eps);
  hydroScale_ = 1.0 / (pi * eps * eps * eps * eps);
  thetaScale_ = 1.0 / (pi * eps * eps);
  if (hydrostatic_) {
    theta_.assign(points(), 0.0);
    kg1_.assign(points(), 0.0);
    dtheta_.assign(points(), 0.0);
    dkg1_.assign(points(), 0.0);
  }
  energyDensity_.assign(points(), 0.0);
}

// r = sqrt|xi| S of pair k of point i (001:(6)): (u_j - u_i) . q with q = e/sqrt|xi| precomputed.
static inline double pairStretch(const BondList& l, std::size_t k, const double* u, double ux, double uy) {
  const std::size_t j = l.neighbour[k];
  return (u[2 * j] - ux) * l.qx(k) + (u[2 * j + 1] - uy) * l.qy(k);
}

void StateBasedModel::hydrostaticStrain(const double* u, double* theta) const {
  // 001:(2): theta_i = sum of omega_j J S |xi| V_j Vbar_ij/(pi eps^2), in blocks as force() below.
  const kernels::ForceArgs args = kernelArgs();
  forEachBlock([&](std::size_t i0, std::size_t i1) { kernels::hydrostaticStrain(args, thetaScale_, i0, i1, u, theta); });
}

void StateBasedModel::updateHydrostatic(const double* u) {
  hydrostaticStrain(u, theta_.data());
  const auto n = static_cast<std::ptrdiff_t>(points());
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::ptrdiff_t i = 0; i < n; ++i) kg1_[i] = bonds_.kappa[i] * material_.g.slope(theta_[i]);
}

kernels::ForceArgs StateBasedModel::kernelArgs() const {
  const StateBasedBonds& b = bonds_;
  return {b.offset.data(), b.neighbour.data(), b.direction.data(), b.q.data(),  b.w.data(),
          b.ws.data(),     b.omega.data(),     material_.f.beta,   tensileScale_, hydroScale_,
          hydrostatic_ ? kg1_.data() : nullptr};
}

template <class Kernel>
void StateBasedModel::forEachBlock(const Kernel& kernel) const {
  // Blocks of points: each block is one call into a vectorized kernel.
  constexpr std::size_t block = 64;
  const std::size_t n = points();
  const auto blocks = static_cast<std::ptrdiff_t>((n + block - 1) / block);
#pragma omp parallel if (parallel_)
  {
    const FlushDenormals flush;
#pragma omp for schedule(static)
    for (std::ptrdiff_t k = 0; k < blocks; ++k) {
      const std::size_t i0 = static_cast<std::size_t>(k) * block;
      kernel(i0, std::min(i0 + block, n));
    }
  }
}

void StateBasedModel::force(const double* u, double* f) {
  if (hydrostatic_) updateHydrostatic(u);
  // 001:(14): 2/(pi eps^2) sum omega_i omega_j J/(eps |xi|) d/dS f(sqrt|xi| S) e V_j Vbar_ij, which with
  // e = sqrt|xi| q and d/dS f = sqrt|xi| f'(r) is (4 c beta/(pi eps^3)) omega_i sum w r exp(-beta r^2) q.
  // 001:(15): (1/(pi eps^4)) omega_i sum omega_j J [g'(theta_j) + g'(theta_i)] e V_j Vbar_ij.
  const kernels::ForceArgs args = kernelArgs();
  forEachBlock([&](std::size_t i0, std::size_t i1) { kernels::stateBasedForce(args, i0, i1, u, f); });
}

void StateBasedModel::tensileEnergyDensity(const double* u, double* e, PreCrack preCrack) const {
  const StateBasedBonds& b = bonds_;
  const double beta = material_.f.beta;
  // 001:(3), (11): (1/(pi eps^2)) sum |xi| omega_i omega_j J/(eps |xi|) f(r) V_j Vbar_ij.
  const auto n = static_cast<std::ptrdiff_t>(points());
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double ux = u[2 * i], uy = u[2 * i + 1];
    double s = 0;
    for (std::size_t k = b.offset[i]; k < b.offset[i + 1]; ++k) {
      const double r = pairStretch(b, k, u, ux, uy);
      s += b.w[k] * -std::expm1(-beta * r * r);  // 1 - exp without cancellation at small strain
    }
    e[i] = energyScale_ * b.omega[i] * s;
  }
  if (preCrack == PreCrack::counted) addPreCrackEnergyDensity(e);
}

void StateBasedModel::addPreCrackEnergyDensity(double* e) const {
  const StateBasedBonds& b = bonds_;
  const BondList& cut = b.preCrack;
  for (std::size_t i = 0; i < points(); ++i) {
    double s = 0;
    for (std::size_t k = cut.offset[i]; k < cut.offset[i + 1]; ++k) s += cut.w[k];  // f saturated at c
    e[i] += energyScale_ * b.omega[i] * s;
  }
}

double StateBasedModel::energy(const double* u) {
  const std::size_t n = points();
  std::vector<double>& e = energyDensity_;
  tensileEnergyDensity(u, e.data());
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) total += e[i];
  if (hydrostatic_) {
    hydrostaticStrain(u, theta_.data());
    const double eps2 = bonds_.horizon * bonds_.horizon;
    for (std::size_t i = 0; i < n; ++i)  // 001:(4): omega(x) g(theta)/eps^2
      total += bonds_.kappa[i] * bonds_.omega[i] * material_.g.value(theta_[i]) / eps2;
  }
  return total * bonds_.cellArea;
}

// Largest r/r* = S/S_c (sqrt|xi| S = r, 001:(6)) over the pairs of point i in list l; 0 without pairs.
static double maxStretchRatio(const BondList& l, std::size_t i, const double* u, double rstar) {
  const double ux = u[2 * i], uy = u[2 * i + 1];
  double r = 0;
  for (std::size_t k = l.offset[i]; k < l.offset[i + 1]; ++k) r = std::max(r, pairStretch(l, k, u, ux, uy));
  return r / rstar;
}

void StateBasedModel::damage(const double* u, double* Z, PreCrack preCrack) const {
  const double rstar = material_.f.inflection();
  const auto n = static_cast<std::ptrdiff_t>(points());
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::ptrdiff_t i = 0; i < n; ++i) Z[i] = maxStretchRatio(bonds_, static_cast<std::size_t>(i), u, rstar);
  if (preCrack == PreCrack::counted) raiseDamageByPreCrack(u, Z);
}

void StateBasedModel::raiseDamageByPreCrack(const double* u, double* Z) const {
  const double rstar = material_.f.inflection();
  for (std::size_t i = 0; i < points(); ++i) Z[i] = std::max(Z[i], maxStretchRatio(bonds_.preCrack, i, u, rstar));
}

}  // namespace peristep
