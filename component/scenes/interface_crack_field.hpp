#pragma once
// Exact near-tip field of a crack on the interface of two isotropic elastic half-planes, plane strain:
// the local solution of 000 Sec. 4.3 (Test 3). The printed field 000:(4.3) is garbled (DESIGN 5.4), so
// it is derived here from Muskhelishvili's complex potentials as in Rice, J. Appl. Mech. 55 (1988) 98,
// and Hutchinson & Suo, Adv. Appl. Mech. 29 (1992) 63, Sec. 2 (the oscillatory field of Williams 1959).
//
// Geometry (as in 000): material 1 (E1) in y > 0, material 2 (E2) in y < 0, same nu; crack faces on
// y = 0+ and y = 0- for x < 0, tip at the origin, bonded interface on x > 0. K = K1 + i K2 is Rice's
// complex stress intensity: sigma_yy + i sigma_xy = K r^(i eps) / sqrt(2 pi r) ahead of the tip.
#include <complex>

#include "models/elastic_scene.hpp"

namespace peristep {

struct PlaneStressState {
  double xx, yy, xy;
};

class InterfaceCrackField {
 public:
  // Throws InvalidInput for non-physical moduli (E <= 0, nu outside (-1, 0.5)) or a non-finite K.
  InterfaceCrackField(double E1, double E2, double nu, double K1 = 1.0, double K2 = 0.0);

  // Bimaterial constant eps = 1/(2 pi) log((kappa1/mu1 + 1/mu2)/(kappa2/mu2 + 1/mu1)), 000:(4.4).
  double epsilon() const { return eps_; }

  // The polar angle is atan2(y, x) in [-pi, pi]: its cut lies on the crack, so the field is continuous
  // across the bonded interface and jumps across the crack. On y = 0 the sign bit of y picks the side:
  // +0.0 is material 1 / the upper crack face, -0.0 material 2 / the lower face.
  Vec2 displacement(double x, double y) const;
  // Unbounded at the tip: throws InvalidInput for x = y = 0.
  PlaneStressState stress(double x, double y) const;

 private:
  // One half-plane. With Phi = phi', Omega = omega' the potentials of Rice (1988) Sec. 2,
  // Phi(z) = own z^(-1/2 - i eps) and Omega(z) = partner z^(-1/2 - i eps), Omega being the other
  // half-plane's Phi (traction continuity on the whole line y = 0).
  struct Phase {
    double mu, kappa;
    std::complex<double> own, partner;
  };
  const Phase& phaseAt(double y) const;

  double eps_;
  Phase upper_, lower_;
};

}  // namespace peristep
