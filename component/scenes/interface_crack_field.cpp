#include "scenes/interface_crack_field.hpp"

#include <cmath>
#include <numbers>

#include "models/lps_material.hpp"

// Derivation (Rice 1988 Sec. 2; Hutchinson & Suo 1992 Sec. 2). In each half-plane, plane strain,
// with Phi = phi', f~(z) = conj(f(conj z)) and Omega = omega' = Phi~ + z Phi~' + Psi~ (Muskhelishvili):
//   2 mu (u_x + i u_y)        = kappa phi(z) - omega(zb) - (z - zb) conj(Phi(z))          (M1)
//   sigma_xx + sigma_yy        = 4 Re Phi(z)                                                (M2)
//   sigma_yy - i sigma_xy      = Phi(z) + Omega(zb) + (z - zb) conj(Phi'(z))                (M3)
// where zb = conj z. On y = 0, (M3) reads Phi_1(x+) + Omega_1(x-) from above and Phi_2(x-) + Omega_2(x+)
// from below. Traction is continuous on the whole line (zero on both faces, equal on the bond), so
// Phi_1 - Omega_2 and Phi_2 - Omega_1 form one entire function, zero for the singular term:
//   Omega_1 = Phi_2,  Omega_2 = Phi_1.
// Equal d/dx of (M1) on the bond x > 0 then gives A1 Phi_1(x+) = A2 Phi_2(x-) with
// A1 = kappa1/mu1 + 1/mu2, A2 = kappa2/mu2 + 1/mu1: h = A_m Phi_m is analytic across the bond. Free
// faces, Phi_1(x+) + Phi_2(x-) = 0 for x < 0, give h+ = -(A1/A2) h- = -exp(2 pi eps) h-, solved by
// h = C z^(-1/2 - i eps) with the cut on the crack. The traction ahead of the tip,
// sigma_yy - i sigma_xy = (1/A1 + 1/A2) h(x), must equal conj(K) x^(-1/2 - i eps)/sqrt(2 pi), so
//   Phi_1 = conj(K) z^(-1/2 - i eps) / (sqrt(2 pi) (1 + exp( 2 pi eps))),
//   Phi_2 = conj(K) z^(-1/2 - i eps) / (sqrt(2 pi) (1 + exp(-2 pi eps))).
// For K = 1 this reproduces the legible parts of 000:(4.3) (u^I, v^I with Pi = +-pi); for eps = 0 the
// Williams/Irwin mode I and II fields.

namespace peristep {

namespace {

using Complex = std::complex<double>;
constexpr double pi = std::numbers::pi;

// z^q and conj(z)^q with arg z = theta = atan2(y, x) in [-pi, pi], so the cut is the crack (faces at
// theta = +-pi). Written out, so the face a point belongs to is decided once, by phaseAt and atan2, and
// does not hinge on how std::pow treats the sign of a zero imaginary part.
Complex zPower(Complex q, double logR, double theta) { return std::exp(q * Complex(logR, theta)); }
Complex zbPower(Complex q, double logR, double theta) { return std::exp(q * Complex(logR, -theta)); }

}  // namespace

InterfaceCrackField::InterfaceCrackField(double E1, double E2, double nu, double K1, double K2) {
  validateElastic(E1, nu);
  validateElastic(E2, nu);
  require(std::isfinite(K1) && std::isfinite(K2), "interface crack: stress intensity K1 + i K2 must be finite");
  const double kappa = 3.0 - 4.0 * nu;  // plane strain
  const double mu1 = planeStrain(E1, nu).mu, mu2 = planeStrain(E2, nu).mu;
  // 000:(4.4) writes the same ratio multiplied through by mu1 mu2: (mu2 kappa1 + mu1)/(mu1 kappa2 + mu2).
  eps_ = std::log((kappa / mu1 + 1.0 / mu2) / (kappa / mu2 + 1.0 / mu1)) / (2.0 * pi);
  const Complex Kbar(K1, -K2);
  const Complex phi1 = Kbar / (std::sqrt(2.0 * pi) * (1.0 + std::exp(2.0 * pi * eps_)));
  const Complex phi2 = Kbar / (std::sqrt(2.0 * pi) * (1.0 + std::exp(-2.0 * pi * eps_)));
  upper_ = {mu1, kappa, phi1, phi2};
  lower_ = {mu2, kappa, phi2, phi1};
}

const InterfaceCrackField::Phase& InterfaceCrackField::phaseAt(double y) const {
  return std::signbit(y) ? lower_ : upper_;
}

Vec2 InterfaceCrackField::displacement(double x, double y) const {
  const double r = std::hypot(x, y);
  if (r == 0.0) return {0.0, 0.0};  // u ~ sqrt(r): the limit at the tip
  const Phase& m = phaseAt(y);
  const double logR = std::log(r), theta = std::atan2(y, x);
  const Complex p(0.5, -eps_);  // phi ~ z^p, p = 1/2 - i eps
  const Complex phi = m.own * zPower(p, logR, theta) / p;
  const Complex omegaOfZb = m.partner * zbPower(p, logR, theta) / p;
  const Complex Phi = m.own * zPower(p - 1.0, logR, theta);
  const Complex zMinusZb(0.0, 2.0 * y);
  const Complex u = (m.kappa * phi - omegaOfZb - zMinusZb * std::conj(Phi)) / (2.0 * m.mu);  // (M1)
  return {u.real(), u.imag()};
}

PlaneStressState InterfaceCrackField::stress(double x, double y) const {
  const double r = std::hypot(x, y);
  require(r > 0.0, "interface crack: the stress is unbounded at the crack tip (x = y = 0)");
  const Phase& m = phaseAt(y);
  const double logR = std::log(r), theta = std::atan2(y, x);
  const Complex p(0.5, -eps_);
  const Complex Phi = m.own * zPower(p - 1.0, logR, theta);
  const Complex dPhi = m.own * (p - 1.0) * zPower(p - 2.0, logR, theta);
  const Complex OmegaOfZb = m.partner * zbPower(p - 1.0, logR, theta);
  const Complex zMinusZb(0.0, 2.0 * y);
  const Complex t = Phi + OmegaOfZb + zMinusZb * std::conj(dPhi);  // (M3): sigma_yy - i sigma_xy
  const double trace = 4.0 * Phi.real();                             // (M2)
  return {trace - t.real(), t.real(), -t.imag()};
}

}  // namespace peristep
