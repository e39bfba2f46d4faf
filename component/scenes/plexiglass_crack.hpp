#pragma once
// 001 Sec. 6.1: dynamic crack growth in a pre-cracked Plexiglass square (Fig. 4), as a preset of the
// dynamic specimen (scenes/specimen.hpp): nothing here but where the grips, the pre-crack and the
// material go.
//
// Set-up chosen here (the paper gives Fig. 4 only in words):
//  - material domain D: the square of the nx x nx cells of side h centred on the points of the specimen's
//    vertex grid (its side L = Lx + h; L = 0.1 m in 001); a collar eps thick above and below D, held by grip
//    boxes (node counts then match 001 Sec. 6.1: 0.9e3, 3.5e3, 13.7e3 at eps = 8 mm);
//  - top collar: u_x held at 0 (u_y free); bottom collar: v_x = -1 m/s left of the crack line and
//    +1 m/s right of it (u_y free), so that the bottom edge is pulled apart;
//  - pre-crack: the vertical segment x = 0 from below the bottom collar up to L/5 above D's bottom face;
//    bonds crossing it are removed. Nodes exactly on the line (odd nx) belong to the left strip.
//  - material of 001 Table 1 (nu = 0.25 by default), rho = 1200 kg/m^3, dt = 0.004 us to T = 34 us.
#include "models/state_based_material.hpp"
#include "scenes/dynamic_scene.hpp"
#include "scenes/specimen.hpp"

namespace peristep {

// The grips, pre-crack and material maps of the square on `grid` (nx = ny), with the material of 001
// (E = 3 K (1 - 2 nu) on every point, so the stiffness factor is 1) and the strips pulled at pullVelocity
// times loadFactor [m/s].
SpecimenSpec plexiglassCrackPreset(const GridSpec& grid, const StateBasedInput& material, double pullVelocity = 1.0);
inline constexpr double kPlexiglassTimeStep = 0.004e-6;  // 001 Sec. 6.1 [s]

// The paper's runs by horizon and mesh ratio, for benches and tests.
struct PlexiglassCrackSpec {
  double horizon = 0.008;        // eps [m]
  double meshRatio = 4;          // eps/h (2, 4, 8 in 001 Sec. 6.1.2)
  // 001 Table 1: K, G_c, rho, nu = 0.25 (nu = 0.22 switches the hydrostatic force on: column "0.245").
  StateBasedInput material;
  double side = 0.1;             // L [m]
  double pullVelocity = 1.0;     // [m/s]
  double timeStep = kPlexiglassTimeStep;
  double endTime = 34e-6;        // [s]
};

// The grid of the spec: L/h points per side spanning L - h.
GridSpec plexiglassCrackGrid(const PlexiglassCrackSpec& spec);
DynamicScene makePlexiglassCrack(const PlexiglassCrackSpec& spec);

}  // namespace peristep
