#pragma once
// What modelDescription.xml and the FMU's documentation/index.html both state about the model as a
// whole, so that the two generators cannot disagree.
#include <charconv>
#include <string>

namespace peristep::fmi {

inline constexpr const char* kModelSummary =
    "Peridynamic solver for randomly heterogeneous materials: quasi-static scenes (smooth, composite, "
    "interfaceCrack, glassCeramic, klPlate) solve once per communication step at the current loadFactor or "
    "loadDisplacement; dynamic fracture scenes (plexiglassCrack, bendingOneNotch, bendingTwoNotches) integrate "
    "the equation of motion over each communication step";

// <DefaultExperiment>: four load increments of the quasi-static scenes, the default scene's run. The
// dynamic scenes need steps of microseconds (their scene descriptions state them): with this step an
// fmi3DoStep would take 0.25 s / 0.004 us = 6.25e7 internal steps.
struct Experiment {
  double startTime, stopTime, stepSize;
};
inline constexpr Experiment kDefaultExperiment{0.0, 1.0, 0.25};

// Shortest decimal text that reads back to x.
inline std::string number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace peristep::fmi
