#pragma once
// The loading programmes of 002 Sec. 4.1 for a GamutBarSolver.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "models/ramberg_osgood.hpp"
#include "solvers/gamut_bar_solver.hpp"

namespace peristep {

struct MonotonicCurve {
  std::vector<double> stress, strain;  // one entry per force step
  std::vector<std::size_t> brokenBonds;
  std::string stopped;  // why the ramp ended before eps_f (the solver's message), or ""
};

// 002 Sec. 4.1: the end force starts at `firstForce` (0.01 N) and grows by `growth` (1%) per step until
// the strain passes eps_f (or `maxSteps` steps). A step without equilibrium ends the curve (`stopped`);
// LinearRangeExceeded is passed on.
MonotonicCurve monotonicLoading(GamutBarSolver& solver, double failureStrain, double firstForce = 0.01,
                                double growth = 0.01, std::size_t maxSteps = 10000);

// Fully reversed, stress-controlled cycles at increasing amplitudes. 002 says only that the force is
// unloaded "in the similar fashion" once the stress passed sigma_y; the stable loops it fits need
// amplitudes above sigma_y, so: `amplitudes` levels evenly from sigma_y to sigma_f (both included); at
// each, the force goes to +F_a and to -F_a in `stepsPerHalfCycle` equal steps per half cycle, and after
// the last one back to +F_a once more to check that the loop closes (it is then stable: the elements
// retrace it cycle after cycle).
struct CyclicProtocol {
  std::vector<double> amplitudes;  // stress amplitudes [Pa]
  int stepsPerHalfCycle = 4;
};
CyclicProtocol gamutCyclicProtocol(const RambergOsgood& material, int amplitudes = 6, int stepsPerHalfCycle = 4);

struct CyclicLoops {
  double modulus = 0;  // the bar's elastic modulus, from a first step of 0.01 N
  std::vector<double> stressAmplitude, strainAmplitude, plasticStrainAmplitude;
  // |strain at the second visit of +F_a - strain at the first| at the largest amplitude: 0 for a loop
  // that closes.
  double closure = 0;
};
// Plastic strain amplitude eps_pa = eps_a - sigma_a / E_bar, with eps_a half the strain range of the loop.
CyclicLoops cyclicLoading(GamutBarSolver& solver, const CyclicProtocol& protocol, double area);

// cyclicLoading in two halves, for a caller that takes the steps one at a time (the FMU's gamutBar scene):
// the end force [N] of every solver step in order (first the 0.01 N step that measures the modulus), and
// the loops from the strains those steps reached. The forces are the doubles cyclicLoading steps to.
std::vector<double> cyclicForces(const CyclicProtocol& protocol, double area);
CyclicLoops cyclicLoops(const CyclicProtocol& protocol, double area, std::span<const double> strains);

}  // namespace peristep
