#pragma once
// The energy report of a dynamic fracture run (001 Sec. 6.1.1, Fig. 6 and 10), printed and written to
// CSV by plexiglass_crack and bending_test. Two readings of the Griffith check side by side:
//   P.E., l        the pre-crack left out: cut pairs are no bonds; l is the growth beyond the pre-crack;
//   P.E.*, l*      the pre-crack counted as broken bonds, as the authors' code does (PreCrack::counted):
//                  Z over the cut pairs too, each holding its saturated energy; l* = pre-crack + growth.
#include <cstdio>

#include "scenes/fracture_diagnostics.hpp"

namespace peristep::bench {

class EnergyTable {
 public:
  EnergyTable(double Gc, const char* csvPath) : Gc_(Gc), csv_(csvPath ? std::fopen(csvPath, "w") : nullptr) {
    if (csv_)
      std::fprintf(csv_, "t_us,kinetic,elastic,work,balance,fracture_energy,crack_length,griffith,max_Z,"
                         "fracture_energy_with_precrack,crack_length_with_precrack,max_Z_with_precrack\n");
    std::printf("%7s %10s %10s %10s %10s %10s %8s %6s %6s | %10s %8s %6s %6s\n", "t[us]", "kinetic", "elastic", "work",
                "balance", "P.E.", "l [mm]", "PE/GE", "max Z", "P.E.*", "l* [mm]", "PE*/GE*", "max Z*");
  }
  ~EnergyTable() {
    if (csv_) std::fclose(csv_);
  }
  EnergyTable(const EnergyTable&) = delete;
  EnergyTable& operator=(const EnergyTable&) = delete;

  void row(const EnergyRecord& e) {
    if (e.time == 0) first_ = e;
    const double ge = Gc_ * e.crackLength, geAll = Gc_ * e.crackLengthWithPreCrack;
    std::printf("%7.1f %10.4e %10.4e %10.4e %10.3e %10.4e %8.3f %6.3f %6.1f | %10.4e %8.3f %7.3f %6.1f\n", e.time * 1e6,
                e.kinetic, e.elastic, e.externalWork, e.balance(first_), e.fractureEnergy, e.crackLength * 1e3,
                ge > 0 ? e.fractureEnergy / ge : 0.0, e.maxDamage, e.fractureEnergyWithPreCrack,
                e.crackLengthWithPreCrack * 1e3, geAll > 0 ? e.fractureEnergyWithPreCrack / geAll : 0.0,
                e.maxDamageWithPreCrack);
    std::fflush(stdout);
    if (csv_)
      std::fprintf(csv_, "%g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", e.time * 1e6, e.kinetic, e.elastic,
                   e.externalWork, e.balance(first_), e.fractureEnergy, e.crackLength, ge, e.maxDamage,
                   e.fractureEnergyWithPreCrack, e.crackLengthWithPreCrack, e.maxDamageWithPreCrack);
  }

 private:
  double Gc_;
  std::FILE* csv_;
  EnergyRecord first_;
};

}  // namespace peristep::bench
