#pragma once
// 000 Sec. 5's measurements of a quasi-static specimen's crack: the crack grown from a pre-crack's tip
// towards +x, its length along the centre line, its shares among glass, crystal and interface, the
// energy release rate 000:(5.2) and K_IC 000:(5.3). Reads the driver's current state on every query.
#include <cstddef>
#include <memory>
#include <vector>

#include "fracture/toughness.hpp"
#include "scenes/glass_ceramic_material.hpp"
#include "solvers/quasi_static_fracture.hpp"

namespace peristep {

class CrackToughness {
 public:
  // `fracture` must outlive this object. (tipX, tipY): the pre-crack's tip; rightEdge: the plate's x = Lx/2;
  // G: fracture energy per cloud point; field: the crystal phase per point and the measured fraction.
  CrackToughness(const QuasiStaticFracture& fracture, double tipX, double tipY, double rightEdge,
                 std::vector<double> G, CrystalField field, PhaseConstants phases);

  // Bonds broken by loading that belong to the crack grown from the tip: chains of broken bonds whose
  // midpoints lie within 1.5 h of each other, started within delta of the tip. Damage elsewhere (e.g. at
  // the corners where the clamped edges meet the free ones) does not count towards the crack.
  std::vector<std::size_t> mainCrackBonds() const;
  // Length of the main crack along its centre line (fracture/toughness.hpp), from the tip.
  double crackLength() const;
  // That length shared among the phases by the broken bonds (000 Sec. 5: L1, L2, L_i).
  CrackShares crackShares() const;
  // Projected crack length W along x, from the tip to the farthest bond of the main crack.
  double projectedCrackLength() const;
  double energyReleaseRate() const;  // 000:(5.2), fracture energy per bond (fracture/toughness.hpp)
  double toughnessKIC() const;       // 000:(5.3)
  // The crack has come within delta of the right edge: the specimen is through.
  bool crackReachedRightEdge() const;
  const CrystalField& field() const { return field_; }

 private:
  double projectedLength(const std::vector<std::size_t>& crack) const;
  double centreLength(const std::vector<std::size_t>& crack, double W) const;

  const QuasiStaticFracture* fracture_;
  double tipX_, tipY_, rightEdge_;
  std::vector<double> G_;
  CrystalField field_;
  PhaseConstants phases_;
};

}  // namespace peristep
