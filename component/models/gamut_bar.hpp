#pragma once
// The discrete 1D bar of 002 (Desai), Eq. (25)/(B.8) in its quasi-static form K_NL U = F: every pair of
// points interacts, neighbours through local bonds (002:(28) C = A E / l), all other pairs through
// nonlocal bonds carrying the share R w of their points' stiffness (002:(24): U_NL = w R U_L, i.e.
// DG_L = DG_NL of 002:(4)), with Gaussian weights w (002:(21)-(22), (31)) and R from 002:(30).
//
// Reading of what 002 leaves to its reference [29] (not available), written down once here:
//  * Unloading. Every bond carries elements (a nonlocal bond one per end point, with that point's w and
//    R). An element is elastic until its force reaches a cap; then it stops absorbing energy, dU/dt = 0
//    (002:(35)): it slips at constant force, keeps the slip when unloaded, reloads elastically and slips
//    again at minus the cap (kinematic, rate independent). This is the reading of "breaking" that gives
//    stable hysteresis loops: an element that dropped its force to zero would release energy (dU/dt < 0,
//    not -> 0), and a bar of such bonds unloads to the origin along a secant, with no loop at all.
//  * Critical strains. 002 Sec. 3.1.3: every point deforms like its equivalent-isotropic material
//    (Ramberg-Osgood with the point's E); 002 Sec. 2: the weight sets the critical deformation of a
//    nonlocal bond. So a point's nonlocal elements slip in the order of their weights, heaviest first;
//    the group with shares S_before -> S_after slips when the point's Ramberg-Osgood tangent modulus has
//    fallen to E (S_before + S_after) / 2. The local bond of each cut (002:(B.4): the part of the force
//    that stays local) takes what the nonlocal elements crossing the cut leave of A sigma_RO(eps) under a
//    uniform strain (gamut_local_bonds.hpp). A homogeneous bar then follows Ramberg-Osgood and its loops
//    are the Masing loops of the classical baseline.
//  * Ends. The bar is fixed at x = 0 and pulled at x = L. Nonlocal bonds reach across both ends into the
//    mirror images of the bar (u(-x) = -u(x), u(2L - x) = 2 u(L) - u(x)), so that a homogeneous bar
//    strains uniformly; 002 does not treat its ends, and without this they carry twice the nonlocal
//    stiffness of the middle.
//  * sigma_stdev of 002:(31) uses the "uncalibrated potentials" of equal springs under a uniform strain
//    (U ~ l^2) and the farthest distance L (gamut_weights.hpp).
//  * Misprints (DESIGN.md 5.6): U = C (l eps)^2 / 2 in (15)/(29); the ratio in (23) is U_i / U_j; (32)
//    follows (22). A draw of R at or beyond 1 (or <= 0) is drawn again (002 says R lies in [0, 1]).
//  * The mass (002:(14), (34)) does not enter the quasi-static problem and is not modelled.
#include <array>
#include <cstdint>
#include <vector>

#include "models/ramberg_osgood.hpp"
#include "random/weibull_scatter.hpp"

namespace peristep {

struct CutCrossing;  // models/gamut_local_bonds.hpp

struct GamutBarSpec {
  RambergOsgood material = gamutMaterial1();
  double length = 0.1;  // L [m]
  double area = 1e-4;   // A [m^2]
  int bonds = 500;      // local bonds; bonds + 1 points
  double gridJitter = 0;         // 0: uniform grid; 0.65: the stochastic grid of 002:(36)
  bool scatterProperties = true;  // E, R and w scattered by 002:(26), independently per point / bond
  ScatterLaw scatter;
  // Nonlocal elements whose normalized weight is below this are left out: each would add less than
  // this fraction of a point's stiffness, and none of them slips before eps_f.
  double weightCutoff = 1e-15;
  std::uint64_t seed = 2023;
};

// Where a bond lies: between points p and q of the bar (q > p + 1), from p or q across x = 0 to the
// mirror image of the other (q >= p), across x = L (q >= p, both < n), or the local bond of the cut
// between p and q = p + 1.
enum class GamutBondKind : std::uint8_t { Inside, AcrossStart, AcrossEnd, Local };
struct GamutBondPoints {
  GamutBondKind kind;
  int p, q;
};

// One realization of the bar: the bonds as linear maps of the unknown displacements and their elements.
class GamutBar {
 public:
  GamutBar(const GamutBarSpec& spec, std::uint64_t realization);

  const GamutBarSpec& spec() const { return spec_; }
  int unknowns() const { return spec_.bonds; }  // u_1 .. u_n; u_0 = 0
  int loadedUnknown() const { return spec_.bonds - 1; }
  const std::vector<double>& positions() const { return x_; }
  // E at the points (after the scatter), for the diagnostics of a realization.
  const std::vector<double>& pointModulus() const { return modulus_; }

  // Bond b: elongation e_b = sum_k coef[b][k] u[unknown[b][k]] (unknown -1: no term), reference length.
  std::size_t bondCount() const { return length_.size(); }
  const std::vector<std::array<int, 3>>& bondUnknowns() const { return unknown_; }
  const std::vector<std::array<double, 3>>& bondCoefficients() const { return coef_; }
  const std::vector<double>& bondLength() const { return length_; }
  const std::vector<GamutBondPoints>& bondPoints() const { return points_; }
  // Elements of bond b are firstElement[b] .. firstElement[b + 1] - 1.
  const std::vector<std::size_t>& firstElement() const { return firstElement_; }
  const std::vector<double>& elementStiffness() const { return stiffness_; }  // N/m
  const std::vector<double>& elementCap() const { return cap_; }              // slip force, N

 private:
  // The steps of the constructor.
  struct PartnerTable;
  std::vector<double> drawProperties(ScatterStream& stream);
  PartnerTable slipLadders(ScatterStream& stream) const;
  std::vector<CutCrossing> addNonlocalBonds(const PartnerTable& table, const std::vector<double>& softness);
  void addLocalBonds(const std::vector<CutCrossing>& crossings);
  void addElement(double k, double strain, double l);
  bool closeBond(std::array<int, 3> nodes, std::array<double, 3> coefs, double l, GamutBondKind kind, std::size_t p,
                 std::size_t q);

  GamutBarSpec spec_;
  std::vector<double> x_, modulus_;
  std::vector<std::array<int, 3>> unknown_;
  std::vector<std::array<double, 3>> coef_;
  std::vector<double> length_;
  std::vector<GamutBondPoints> points_;
  std::vector<std::size_t> firstElement_;
  std::vector<double> stiffness_, cap_;
};

}  // namespace peristep
