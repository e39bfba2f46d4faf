#pragma once
// 001 Sec. 6.2: a pre-cracked Plexiglass beam under a growing three-point bending load (Fig. 8), as a
// preset of the dynamic specimen (scenes/specimen.hpp).
//
// Set-up chosen here (001 Fig. 8 is described only in words), on the 0.25 x 0.05 m beam and scaled with it:
//  - material domain D: the nx x ny cells of side h centred on the points of the specimen's vertex grid
//    (length Lx + h, depth Ly + h), no collar;
//  - one pre-crack of length 0.015 m at the middle, or two of the same length 0.02 m either side of it
//    (001 does not give their length), rising from the bottom face;
//  - supports: grip boxes holding u_y at 0 on the nodes within eps of the bottom face with
//    |x - 0.025| <= 0.01 or |x - 0.225| <= 0.01 from the left face (span 0.2 m, symmetric about the cracks);
//  - load: a body force along -y on the top band of depth d = 0.75 mm (one horizon of 001) with
//    |x - mid| <= 0.025, zero at the ends of that line and f_max t at its middle,
//    b_y = f_max t (1 - |x - mid|/0.025), f_max = -2.5e14 N/(m^3 s) (001 Fig. 8). On a coarser lattice
//    the band is the top rows of nodes covering d (at least one row) and b is scaled by d over their
//    depth, so that the resultant load per unit thickness does not depend on the resolution;
//  - nu = 0.25 (Table 1), eps = 0.75 mm, h = 0.25 mm, dt = 0.0035 us to T = 350 us in 001.
#include "models/state_based_material.hpp"
#include "scenes/dynamic_scene.hpp"
#include "scenes/specimen.hpp"

namespace peristep {

// Where the beam's features sit on the 0.25 x 0.05 m beam of 001 (scaled to the grid's beam).
struct BendingLayout {
  double crackLength = 0.015;     // [m]
  double crackOffset = 0.02;      // two cracks: distance of each from the midpoint [m]
  double supportCentre = 0.025, supportHalfWidth = 0.01;    // from each end [m]
  double loadHalfWidth = 0.025;   // [m]
  double loadDepth = 0.75e-3;     // d [m]
  double loadRate = -2.5e14;      // f_max [N/(m^3 s)]
};
inline constexpr double kBeamLength = 0.25, kBeamDepth = 0.05;  // 001's beam [m]
inline constexpr double kBendingTimeStep = 0.0035e-6;           // 001 Sec. 6.2 [s]

// The grips, pre-cracks, load band and material maps of the beam on `grid` with `cracks` (1 or 2) notches.
SpecimenSpec bendingPreset(const GridSpec& grid, int cracks, const StateBasedInput& material,
                           const BendingLayout& layout = {});

// The paper's runs by horizon and mesh ratio, for benches and tests.
struct BendingSpec {
  int cracks = 1;                 // 1 or 2
  double horizon = 0.75e-3;       // eps [m]
  double meshRatio = 3;           // eps/h
  double length = kBeamLength, depth = kBeamDepth;  // [m]
  BendingLayout layout;           // on the 0.25 x 0.05 m beam: scaled by length/0.25 and depth/0.05
  double timeStep = kBendingTimeStep, endTime = 350e-6;  // [s]
  StateBasedInput material;       // 001 Table 1 (nu = 0.25 in Sec. 6.2)
};

DynamicScene makeBendingTest(const BendingSpec& spec);

}  // namespace peristep
