#pragma once
// A stiff test problem for the implicit integrator (DESIGN 7): a plate of the 001 Table 1 material
// (nu = 0.25) with disc inclusions whose modulus is `contrast` times the matrix's (density unchanged),
// clamped along its left edge and pulled by a body force on its right edge that rises smoothly,
//   b_x(t) = b0 sin^2(pi t/(2 t_r)) for t < t_r, b0 afterwards.
// The inclusions' internal vibrations are sqrt(contrast) times faster than anything the load excites:
// they set the explicit stability limit while the response is slow, the textbook stiff case.
#include "scenes/dynamic_scene.hpp"

namespace peristep {

struct StiffInclusionsSpec {
  std::size_t nx = 40, ny = 20;    // lattice nodes
  double h = 1e-3;                 // [m]
  double meshRatio = 3;            // eps/h
  double contrast = 1e3;           // inclusion modulus / matrix modulus
  double inclusionRadius = 3e-3;   // [m]
  double load = 2e9;               // b0 [N/m^3]: about 1e-5 strain, far below the softening strain
  double rampTime = 20e-6;         // t_r [s]
  double endTime = 40e-6;          // [s]
};

// Inclusions on a regular 3 x 2 pattern over the plate; the scene's timeStep is left at 0 (the
// explicit integrators take it from their stability limit or tolerance).
DynamicScene makeStiffInclusions(const StiffInclusionsSpec& spec);

}  // namespace peristep
