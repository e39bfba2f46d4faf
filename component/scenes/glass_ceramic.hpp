#pragma once
// The pre-cracked glass-ceramic specimen of 000 Sec. 5: an 800 x 400 um plate with a 100 um pre-crack from
// the left edge at mid-height, opened by displacing the top and bottom collars; left and right edges free.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fracture/toughness.hpp"
#include "solvers/quasi_static_fracture.hpp"

namespace peristep {

struct GlassCeramicSpec {
  GridSpec grid{401, 201, 800e-6, 400e-6, 3.0};  // h = 2 um, delta = 3h: 413 x 213 = 87969 points
  double crystalFraction = 0.2;
  std::uint64_t seed = 1;
  double preCrackLength = 100e-6;
  PhaseConstants phases{80e9, 133e9, 6.59, 86.35, 0.25};  // 000 Table 1
  LinearSolverKind linearSolver = LinearSolverKind::Umfpack;  // the drivers other than CrackZone
  // The production driver, also behind the FMU (it had stayed StaleAsPreconditioner there: 146 s instead of
  // ~20 s per h = 8 um specimen through `peristep run`, bench/README.md "Issue 14, session 10").
  FactorizationReuse reuse = FactorizationReuse::CrackZone;
  FactorPrecision zonePrecision = kZoneFactorPrecision;  // CrackZone's sparse factors
  // Crystal field R per point (collar included), e.g. the PCA expansion 000:(5.5); empty: the
  // microstructure generated from `seed`. E and G are affine in R; the crack shares count a point with
  // R >= 1/2 as crystal.
  std::vector<double> crystalField;
};

class GlassCeramicSpecimen {
 public:
  explicit GlassCeramicSpecimen(const GlassCeramicSpec& spec);

  // Opening U_D: the top collar moves by (0, +U_D), the bottom collar by (0, -U_D) (x held).
  LoadStepReport advance(double openingDisplacement);

  const QuasiStaticFracture& solver() const { return *fracture_; }
  double measuredCrystalFraction() const { return fraction_; }
  // Fields on the domain points, image order.
  std::vector<double> ux() const;
  std::vector<double> uy() const;
  std::vector<double> damage() const;
  std::vector<double> youngsModulus() const;
  // y-force of the top collar on the specimen per unit thickness [N/m].
  double reactionForce() const;
  // Bonds broken by loading that belong to the crack grown from the pre-crack tip: chains of broken bonds
  // whose midpoints lie within 1.5 h of each other, started at the tip. Damage elsewhere (e.g. at the
  // corners where the clamped edges meet the free ones) does not count towards the crack.
  std::vector<std::size_t> mainCrackBonds() const;
  // Length of the main crack along its centre line (fracture/toughness.hpp), from the pre-crack tip.
  double crackLength() const;
  // That length shared among the phases by the broken bonds (000 Sec. 5: L1, L2, L_i).
  CrackShares crackShares() const;
  // Projected crack length W along x, from the pre-crack tip to the farthest bond of the main crack.
  double projectedCrackLength() const;
  double energyReleaseRate() const;  // 000:(5.2), fracture energy per bond (fracture/toughness.hpp)
  double toughnessKIC() const;       // 000:(5.3)
  bool crackReachedRightEdge() const;

  std::vector<std::uint8_t> saveState() const { return fracture_->saveState(); }
  void restoreState(std::span<const std::uint8_t> b) { fracture_->restoreState(b); }
  void onSubIteration(std::function<void(const LoadStepReport&)> hook) { fracture_->onSubIteration(std::move(hook)); }

 private:
  std::vector<double> domainValues(const std::vector<double>& perPoint) const;
  // W and the centre-line length of a crack given by its bonds (each query searches the main crack once).
  double projectedLength(const std::vector<std::size_t>& crack) const;
  double centreLength(const std::vector<std::size_t>& crack, double W) const;

  GlassCeramicSpec spec_;
  std::shared_ptr<const LpsDiscretization> disc_;
  std::vector<std::uint8_t> crystal_, topCollar_;
  std::vector<double> E_, G_;
  double fraction_ = 0, tipX_ = 0;
  std::unique_ptr<QuasiStaticFracture> fracture_;
};

}  // namespace peristep
