#pragma once
// The local bonds of the 002 bar, calibrated cut by cut. Under a uniform strain eps every cut between
// neighbouring points carries the force of the local bond plus that of every nonlocal element whose bond
// crosses it; the local bond is given the remainder of A sigma_RO(eps) of its point (002 Sec. 3.1.3: every
// point deforms like its equivalent-isotropic Ramberg-Osgood material; 002:(B.4): the local bond keeps
// the part of the force that is not nonlocalized). It is a bundle of elastic-slipping elements (the same
// law as the nonlocal elements) whose curve passes through the remainder at a set of knot strains.
#include <cstddef>
#include <span>
#include <vector>

namespace peristep {

// A bond crosses the cuts first .. end - 1 `multiplicity` times (mirrored bonds cross twice or once).
struct CutCrossing {
  std::size_t bond;
  std::size_t first, end;
  double multiplicity;
};

// Force through each cut from the nonlocal elements at each knot strain: [cut * knots.size() + knot].
// An element of stiffness k (N/m) and cap c on a bond of length l carries min(k l eps, c).
std::vector<double> nonlocalCutForces(std::span<const CutCrossing> crossings, std::span<const std::size_t> firstElement,
                                      std::span<const double> stiffness, std::span<const double> cap,
                                      std::span<const double> bondLength, std::span<const double> knots, std::size_t cuts);

// Elements of a local bond (force per unit strain, N, and critical strain) whose summed curve is the
// piecewise-linear interpolation of `remainder` (force at the knot strains, 0 at strain 0) where that is
// nondecreasing and concave, its least concave majorant elsewhere; the slope of the last segment stays
// beyond it as an element that never slips.
struct LocalBundle {
  std::vector<double> stiffness, strain;
};
LocalBundle localBundle(std::span<const double> knots, std::span<const double> remainder);

// Knot strains: `count` geometric steps from a quarter of the yield strain to twice eps_f, then 4 eps_f.
std::vector<double> localKnots(double yieldStrain, double failureStrain, int count = 24);

}  // namespace peristep
