#pragma once
// 001 Sec. 6.2: a pre-cracked Plexiglass beam under a growing three-point bending load (Fig. 8).
//
// Set-up chosen here (001 Fig. 8 is described only in words):
//  - material domain D = [0, 0.25] x [0, 0.05] m, cell-centred square cells of side h, no collar;
//  - one pre-crack of length 0.015 m at x = 0.125 m, or two of the same length at x = 0.105 and
//    0.145 m (0.02 m either side of the midpoint; 001 does not give their length), rising from y = 0;
//  - supports: the nodes within eps of the bottom edge with |x - 0.025| <= 0.01 or |x - 0.225| <= 0.01
//    have u_y held at 0 (span 0.2 m, symmetric about the cracks);
//  - load: a body force along -y on the top band of depth d = 0.75 mm (one horizon of 001) with
//    |x - 0.125| <= 0.025, zero at the ends of that line and f_max t at its middle,
//    b_y = f_max t (1 - |x - 0.125|/0.025), f_max = -2.5e14 N/(m^3 s) (001 Fig. 8). On a coarser lattice
//    the band is the top rows of nodes covering d (at least one row) and b is scaled by d over their
//    depth, so that the resultant load per unit thickness does not depend on the resolution;
//  - nu = 0.25 (Table 1), eps = 0.75 mm, h = 0.25 mm, dt = 0.0035 us to T = 350 us in 001.
#include "models/state_based_material.hpp"
#include "scenes/dynamic_scene.hpp"

namespace peristep {

struct BendingSpec {
  int cracks = 1;                 // 1 or 2
  double horizon = 0.75e-3;       // eps [m]
  double meshRatio = 3;           // eps/h
  double length = 0.25, depth = 0.05, crackLength = 0.015;  // [m]
  double crackOffset = 0.02;      // two cracks: distance of each from the midpoint [m]
  double supportCentre = 0.025, supportHalfWidth = 0.01;    // from each end [m]
  double loadHalfWidth = 0.025;   // [m]
  double loadDepth = 0.75e-3;     // d [m]
  double loadRate = -2.5e14;      // f_max [N/(m^3 s)]
  double timeStep = 0.0035e-6, endTime = 350e-6;  // [s]
  StateBasedInput material;       // 001 Table 1 (nu = 0.25 in Sec. 6.2)
};

DynamicScene makeBendingTest(const BendingSpec& spec);

}  // namespace peristep
