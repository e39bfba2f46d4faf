#pragma once
// Crack lengths by phase from broken bonds, and fracture toughness 000:(5.2)-(5.3).
#include <cstddef>
#include <vector>

#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"

namespace peristep {

// A straight crack in a cloud of density 1/h^2 cuts int_{B_delta, z.n>0} (z.n) dz / h^4 = 2 delta^3/(3 h^4)
// bonds per unit length (for delta = 3h on a lattice: exactly 18 per h). So one broken bond stands for
// 3 h^4 / (2 delta^3) of crack length.
double crackLengthPerBond(double h, double delta);

struct CrackShares {
  double glass = 0, crystal = 0, interface = 0;  // lengths [m]: bonds glass-glass, crystal-crystal, mixed
  double total() const { return glass + crystal + interface; }
};

// bonds: CSR positions of broken pairs; crystal: per point, 1 in the crystal phase.
CrackShares crackShares(const PointCloud& cloud, const Neighbours& nb, const std::vector<std::size_t>& bonds,
                        const std::vector<std::uint8_t>& crystal);

struct PhaseConstants {
  double E1, E2, G1, G2, nu;  // glass (1) and crystal (2), 000 Table 1
};

// Numerator of 000:(5.2): every broken bond contributes its fracture energy, the arithmetic mean of its
// ends' G (000:(2.26)), times the crack length one bond stands for. For a two-phase field this is exactly
// G1 L1 + G2 L2 + G_i L_i with G_i = (G1 + G2)/2; it extends (5.2) to a continuous field such as the PCA
// expansion 000:(5.5), where the phase shares alone would miss the G of intermediate points.
double crackEnergy(const PointCloud& cloud, const Neighbours& nb, const std::vector<std::size_t>& bonds,
                   const std::vector<double>& G);
// 000:(5.3): K_IC = sqrt(G_IC E_eff/(1-nu^2)), E_eff = (1-f) E1 + f E2.
double toughnessKIC(double GIC, double crystalFraction, const PhaseConstants& m);

}  // namespace peristep
