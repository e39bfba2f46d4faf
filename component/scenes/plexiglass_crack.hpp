#pragma once
// 001 Sec. 6.1: dynamic crack growth in a pre-cracked Plexiglass square (Fig. 4).
//
// Set-up chosen here (the paper gives Fig. 4 only in words):
//  - material domain D = [0, L]^2, L = 0.1 m, meshed with cell-centred square cells of side h; a collar
//    of thickness eps is added above and below D (node counts then match 001 Sec. 6.1: 0.9e3, 3.5e3,
//    13.7e3 at eps = 8 mm);
//  - top collar: u_x held at 0 (u_y free); bottom collar: v_x = -1 m/s left of the crack line and
//    +1 m/s right of it (u_y free), so that the bottom edge is pulled apart;
//  - pre-crack: the vertical segment x = L/2 from the bottom of the collar up to y = 0.02 m; bonds
//    crossing it are removed. Nodes exactly on the line (h = eps/2 = 4 mm) belong to the left face.
//  - material of 001 Table 1 (nu = 0.25 by default), rho = 1200 kg/m^3, dt = 0.004 us to T = 34 us.
#include "models/state_based_material.hpp"
#include "scenes/dynamic_scene.hpp"

namespace peristep {

struct PlexiglassCrackSpec {
  double horizon = 0.008;        // eps [m]
  double meshRatio = 4;          // eps/h (2, 4, 8 in 001 Sec. 6.1.2)
  // 001 Table 1: K, G_c, rho, nu = 0.25 (nu = 0.22 switches the hydrostatic force on: column "0.245").
  StateBasedInput material;
  double side = 0.1;             // L [m]
  double crackLength = 0.02;     // [m]
  double pullVelocity = 1.0;     // [m/s]
  double timeStep = 0.004e-6;    // [s]
  double endTime = 34e-6;        // [s]
};

DynamicScene makePlexiglassCrack(const PlexiglassCrackSpec& spec);

}  // namespace peristep
