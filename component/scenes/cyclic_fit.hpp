#pragma once
// Cyclic stress-strain curve sigma_a = K' eps_pa^n' (cyclic Ramberg-Osgood): the least-squares line of
// log stress amplitude against log plastic strain amplitude of the stable loops (002 Sec. 4.4.3, the
// "poly1" fit of its Figs. 27-28), slope n', intercept log K'.
#include <span>

namespace peristep {

struct CyclicFit {
  double exponent = 0;     // n'
  double coefficient = 0;  // K', in the unit of the stresses
};

// Needs at least two points with positive plastic strain amplitude; throws InvalidInput otherwise.
CyclicFit fitCyclicCurve(std::span<const double> stressAmplitude, std::span<const double> plasticStrainAmplitude);

}  // namespace peristep
