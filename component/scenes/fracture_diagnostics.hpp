#pragma once
// Energy bookkeeping of a dynamic fracture run (001 Sec. 6.1.1): kinetic and elastic energy, work of
// the loads, peridynamic energy of the crack zone Z > 1 (001:(104)) and crack length.
#include <vector>

#include "scenes/dynamic_scene.hpp"
#include "solvers/time_integrator.hpp"

namespace peristep {

struct EnergyRecord {
  double time = 0;
  double kinetic = 0, elastic = 0, externalWork = 0;  // [J per m of thickness]
  double fractureEnergy = 0;   // P.E.: tensile energy of the points of D with Z > 1
  double crackLength = 0;      // sum over pre-cracks of the growth of their Z > 1 zone beyond the tip [m]
  double maxDamage = 0;        // max Z over D
  // The same with the pre-crack counted as broken bonds, as in the authors' code (PreCrack::counted):
  // Z and P.E. over the cut pairs too, and the length is the pre-crack's length in D plus the growth.
  double fractureEnergyWithPreCrack = 0, crackLengthWithPreCrack = 0, maxDamageWithPreCrack = 0;
  // Energy balance residual against the initial record: kinetic + elastic - work - (kinetic0 + elastic0),
  // zero when energy is conserved.
  double balance(const EnergyRecord& initial) const {
    return kinetic + elastic - externalWork - (initial.kinetic + initial.elastic);
  }
};

class FractureDiagnostics {
 public:
  explicit FractureDiagnostics(DynamicScene& scene);

  EnergyRecord measure(const TimeIntegrator& integrator);
  const std::vector<double>& damage() const { return Z_; }  // Z of the last measure()

 private:
  // Crack growth: the length of crack c is the largest advance (x - tip) . direction over the points of its
  // zone (crackZoneOwners, Z given).
  std::vector<double> crackLengths(const std::vector<double>& Z) const;
  double lengthInMaterial(const Segment& s) const;

  DynamicScene& scene_;
  std::vector<double> Z_, energyDensity_, ZWithPreCrack_, energyWithPreCrack_;
};

}  // namespace peristep
