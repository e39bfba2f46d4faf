#pragma once
// The equivalent-isotropic material of a point of the 002 bar: Ramberg-Osgood strain
//   eps(sigma) = sigma / E + K_ro (sigma / sigma_y)^n_ro                                   (002 Sec. 3.1.3)
// with the failure point (sigma_f, eps_f) that enters the modulus of softness R (002:(17)/(18)/(30)).
// Stresses in Pa.

namespace peristep {

struct RambergOsgood {
  double youngsModulus = 0;  // E
  double yieldStress = 0;    // sigma_y
  double failureStress = 0;  // sigma_f
  double failureStrain = 0;  // eps_f
  double exponent = 0;       // n_ro
  double yieldOffset = 0.002;  // K_ro

  // eps(sigma), odd in sigma.
  double strain(double stress) const;
  // The stress at which the tangent modulus d sigma / d eps equals `tangent` (0 < tangent < E): the
  // closed-form inverse of 1 / E_t = 1 / E + K_ro n_ro sigma^(n_ro - 1) / sigma_y^n_ro.
  double stressAtTangent(double tangent) const;
  // d sigma / d eps at the stress sigma >= 0.
  double tangent(double stress) const;
  // sigma(eps) for eps >= 0 (Newton on the monotone eps(sigma)).
  double stress(double strain) const;
  // R = U_S / (U_S + U_T) of 002:(17), with E replaced by `localModulus` as in 002:(30).
  double softness(double localModulus) const;
  // The classical baseline of cyclic plasticity: Masing loops on this curve give sigma_a = K' eps_pa^n'
  // with n' = 1 / n_ro and K' = sigma_y K_ro^(-1/n_ro).
  double masingExponent() const { return 1.0 / exponent; }
  double masingCoefficient() const;
};

// 002 Sec. 4.2, Material 1 and Material 2.
RambergOsgood gamutMaterial1();
RambergOsgood gamutMaterial2();

}  // namespace peristep
