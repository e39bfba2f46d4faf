#pragma once
// The pre-cracked glass-ceramic specimen of 000 Sec. 5: an 800 x 400 um plate with a 100 um pre-crack from
// the left edge at mid-height, opened by displacing the top and bottom collars; left and right edges free.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fracture/toughness.hpp"
#include "scenes/crack_toughness.hpp"
#include "scenes/fracture_specimen.hpp"
#include "solvers/quasi_static_fracture.hpp"

namespace peristep {

struct GlassCeramicSpec {
  GridSpec grid{401, 201, 800e-6, 400e-6, 3.0};  // h = 2 um, delta = 3h: 413 x 213 = 87969 points
  double crystalFraction = 0.2;
  std::uint64_t seed = 1;
  double preCrackLength = 100e-6;
  PhaseConstants phases{80e9, 133e9, 6.59, 86.35, 0.25};  // 000 Table 1
  LinearSolverKind linearSolver = LinearSolverKind::Umfpack;  // the drivers other than CrackZone
  // The production driver, also behind the FMU (with StaleAsPreconditioner an h = 8 um specimen took 146 s
  // through `peristep run`, 46 s with this; docs/decisions/0003-crack-zone-driver.md).
  FactorizationReuse reuse = FactorizationReuse::CrackZone;
  FactorPrecision zonePrecision = kZoneFactorPrecision;  // CrackZone's sparse factors
  // Crystal field R per point (collar included), e.g. the PCA expansion 000:(5.5); empty: the
  // microstructure generated from `seed`. E and G are affine in R; the crack shares count a point with
  // R >= 1/2 as crystal.
  std::vector<double> crystalField;
};

// The scene as a specimen (scenes/specimen.hpp): bottom and top grips held, moved by -U_D and +U_D in y
// (x held), left and right free, the pre-crack along y = 0 from beyond the left edge (x = -Lx/2 - 2 delta)
// to its tip, the material generated (SpecimenMaterial::GlassCeramic), the grips driven by loadDisplacement.
SpecimenSpec glassCeramicPreset(const GridSpec& grid, double preCrackLength);

// bench/glass_ceramic's and the tests' face of that specimen.
class GlassCeramicSpecimen {
 public:
  explicit GlassCeramicSpecimen(const GlassCeramicSpec& spec);

  // Opening U_D: the top collar moves by (0, +U_D), the bottom collar by (0, -U_D) (x held).
  LoadStepReport advance(double openingDisplacement) { return b_.fracture->advance(openingDisplacement); }

  const QuasiStaticFracture& solver() const { return *b_.fracture; }
  double measuredCrystalFraction() const { return toughness_->field().fraction; }
  // Fields on the domain points, image order.
  std::vector<double> ux() const { return onDomain(0); }
  std::vector<double> uy() const { return onDomain(1); }
  std::vector<double> damage() const;
  std::vector<double> youngsModulus() const;
  // y-force of the top collar on the specimen per unit thickness [N/m].
  double reactionForce() const;
  // The crack's measurements (scenes/crack_toughness.hpp).
  std::vector<std::size_t> mainCrackBonds() const { return toughness_->mainCrackBonds(); }
  double crackLength() const { return toughness_->crackLength(); }
  CrackShares crackShares() const { return toughness_->crackShares(); }
  double projectedCrackLength() const { return toughness_->projectedCrackLength(); }
  double energyReleaseRate() const { return toughness_->energyReleaseRate(); }
  double toughnessKIC() const { return toughness_->toughnessKIC(); }
  bool crackReachedRightEdge() const { return toughness_->crackReachedRightEdge(); }

  std::vector<std::uint8_t> saveState() const { return b_.fracture->saveState(); }
  void restoreState(std::span<const std::uint8_t> b) { b_.fracture->restoreState(b); }
  void onSubIteration(std::function<void(const LoadStepReport&)> hook) { b_.fracture->onSubIteration(std::move(hook)); }

 private:
  std::vector<double> onDomain(int component) const;

  FractureSpecimen b_;
  std::unique_ptr<CrackToughness> toughness_;
};

}  // namespace peristep
