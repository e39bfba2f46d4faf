#pragma once
// Crack lengths by phase from broken bonds, and fracture toughness 000:(5.2)-(5.3).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"

namespace peristep {

struct CrackShares {
  double glass = 0, crystal = 0, interface = 0;  // lengths [m]: bonds glass-glass, crystal-crystal, mixed
  double total() const { return glass + crystal + interface; }
};

// Length of the crack formed by the broken pairs `bonds` (CSR positions), measured along its centre
// line from (x0, y0) to x = xEnd: the bonds' midpoints are binned in columns of width h along x, and the
// line joins the mean y of consecutive occupied columns. A count of broken bonds would not do: the band
// of broken bonds is wider than the one line of bonds a crack must cut and zig-zags on the lattice, so a
// straight crack would measure 1.2 times its length (h = 16 um, pure glass). Being a mean per column, the
// line rounds corners sharper than about delta and takes overlapping branches as one.
double centreLineLength(const PointCloud& cloud, const Neighbours& nb, const std::vector<std::size_t>& bonds,
                        double x0, double y0, double xEnd);

// Crack length `length` shared among glass, crystal and interface in proportion to the broken bonds
// glass-glass, crystal-crystal and mixed (crystal: per point, 1 in the crystal phase).
CrackShares crackShares(const Neighbours& nb, const std::vector<std::size_t>& bonds,
                        const std::vector<std::uint8_t>& crystal, double length);

struct PhaseConstants {
  double E1, E2, G1, G2, nu;  // glass (1) and crystal (2), 000 Table 1
};

// Numerator of 000:(5.2): the crack length times the mean fracture energy of its broken bonds (each the
// arithmetic mean of its ends' G, 000:(2.26)). For a two-phase field this is exactly G1 L1 + G2 L2 + G_i L_i
// with G_i = (G1 + G2)/2 and the shares above; it extends (5.2) to a continuous field such as the PCA
// expansion 000:(5.5), where the phase shares alone would miss the G of intermediate points.
double crackEnergy(const Neighbours& nb, const std::vector<std::size_t>& bonds,
                   const std::vector<double>& G, double length);
// 000:(5.3): K_IC = sqrt(G_IC E_eff/(1-nu^2)), E_eff = (1-f) E1 + f E2.
double toughnessKIC(double GIC, double crystalFraction, const PhaseConstants& m);

}  // namespace peristep
