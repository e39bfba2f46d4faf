#pragma once
// Bond state of brittle LPS fracture: gamma of 000:(2.24)/(3.17), critical stretch 000:(2.25),
// pre-cracks, damage 000:(3.23). Only scenes that can break allocate it.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"
#include "geometry/segments.hpp"

namespace peristep {

struct BondState {
  std::vector<std::uint8_t> intact;     // gamma per CSR entry; bond i->j and j->i always agree
  std::vector<std::size_t> reverse;     // CSR position of the reverse bond
  std::vector<double> criticalStretch;  // s0 per CSR entry; infinite where the bond cannot break

  std::size_t bonds() const { return intact.size(); }
};

// Bonds to Void points start broken and stay so; only bonds between two domain points can break (the
// Dirichlet collar is the grip: it moves as prescribed and does not tear off the specimen).
// s0 = sqrt(G_ij / (4(lambda_ij-mu_ij) beta' + 8 mu_ij beta)), beta = beta' = 3 delta/(4 pi), with
// harmonic-mean moduli and arithmetic-mean G (000:(2.25)-(2.26)).
BondState makeBondState(const PointCloud& cloud, const Neighbours& nb, const std::vector<double>& lambda,
                        const std::vector<double>& mu, const std::vector<double>& fractureEnergy);

// Breaks every bond whose segment crosses the pre-crack; returns the number of pairs broken. A point on
// the crack line counts as lying on its positive side (left of the direction x0 -> x1).
std::size_t breakCrossing(BondState& s, const PointCloud& cloud, const Neighbours& nb, const Segment& crack);

// Breaks every intact, breakable bond whose stretch
// s = (|x_j - x_i + u_j - u_i| - |x_j - x_i|)/|x_j - x_i| exceeds s0 and returns the CSR positions of the
// newly broken pairs (one entry per pair, from the lower point index). u holds (u_x, u_y) of every point.
std::vector<std::size_t> breakOverstretched(BondState& s, const PointCloud& cloud, const Neighbours& nb,
                                            const std::vector<double>& u);

// The bonds breakOverstretched would break (not breaking them), and whether that verdict holds for every u'
// within uError of u in each component: no intact breakable bond has |s - s0| <= 2 sqrt(2) uError / |x_j - x_i|.
struct OverstretchVerdict {
  std::vector<std::size_t> bonds;
  bool certain = true;
};
OverstretchVerdict findOverstretched(const BondState& s, const PointCloud& cloud, const Neighbours& nb,
                                     const std::vector<double>& u, double uError);
// Breaks the pairs at these CSR positions (both directions).
void breakBonds(BondState& s, std::span<const std::size_t> bonds);

// Per point, the largest stretch / s0 over its intact breakable bonds (0 if none): how close it is to
// breaking; the fracture driver places its crack zone by it.
std::vector<double> stretchRatios(const BondState& s, const PointCloud& cloud, const Neighbours& nb,
                                  const std::vector<double>& u);

// The bonds of a plate that cannot break (the elastic model): per CSR entry, 0 for bonds to Void and bonds
// crossing one of the pre-cracks (as breakCrossing cuts them), 1 for the rest.
std::vector<std::uint8_t> intactBonds(const PointCloud& cloud, const Neighbours& nb, const std::vector<Segment>& cracks);

// 000:(3.23) over the material bonds (bonds to Void are not counted): the broken fraction of a point's
// bonds, on the domain points in image order.
std::vector<double> damageField(const std::vector<std::uint8_t>& intact, const PointCloud& cloud, const Neighbours& nb);
inline std::vector<double> damageField(const BondState& s, const PointCloud& cloud, const Neighbours& nb) {
  return damageField(s.intact, cloud, nb);
}

// Number of broken pairs between material points (pre-crack included).
std::size_t brokenPairs(const std::vector<std::uint8_t>& intact, const PointCloud& cloud, const Neighbours& nb);
inline std::size_t brokenPairs(const BondState& s, const PointCloud& cloud, const Neighbours& nb) {
  return brokenPairs(s.intact, cloud, nb);
}

}  // namespace peristep
