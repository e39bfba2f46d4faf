#include "scenes/glass_ceramic.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "models/lps_material.hpp"
#include "core/timer.hpp"
#include "quadrature/optimization_weights.hpp"
#include "scenes/microstructure.hpp"

namespace peristep {

GlassCeramicSpecimen::GlassCeramicSpecimen(const GlassCeramicSpec& spec) : spec_(spec) {
  const PhaseConstants& m = spec.phases;
  validateElastic(m.E1, m.nu);
  validateElastic(m.E2, m.nu);
  require(m.G1 > 0 && m.G2 > 0 && std::isfinite(m.G1) && std::isfinite(m.G2), "fracture energies must be positive");
  require(spec.preCrackLength >= 0 && spec.preCrackLength < spec.grid.Lx, "pre-crack must be shorter than the plate");
  validate(spec.grid);

  GridSpec grid = spec.grid;
  grid.collar = true;
  LpsDiscretization d;
  d.cloud = makeRectangle(grid);
  d.cloud.freeSideEdges();  // 000 Sec. 5: only top and bottom are loaded; the other edges are free
  Stopwatch clock;
  d.neighbours = findNeighbours(d.cloud, d.cloud.delta);
  d.dofs = numberDofs(d.cloud, d.neighbours);
  d.neighbourSeconds = clock.lap();
  // Weights on the full neighbourhood, Void points included: the broken-bond weights w^ of 000:(3.18)
  // then integrate over the part of the ball outside the material.
  d.weights = optimizationWeights(d.cloud, d.neighbours, std::vector<char>(d.cloud.size(), 1));
  d.weightSeconds = clock.lap();
  disc_ = std::make_shared<const LpsDiscretization>(std::move(d));
  const PointCloud& c = disc_->cloud;

  crystal_ = generateMicrostructure(c, spec.crystalFraction, spec.seed);
  fraction_ = crystalFraction(c, crystal_);
  FractureMaterial mat;
  const Lame glass = planeStrain(m.E1, m.nu), crystal = planeStrain(m.E2, m.nu);
  for (std::size_t p = 0; p < c.size(); ++p) {  // 000 Sec. 5: E and G linear in R
    const bool r = crystal_[p];
    E_.push_back(r ? m.E2 : m.E1);
    mat.lambda.push_back(r ? crystal.lambda : glass.lambda);
    mat.mu.push_back(r ? crystal.mu : glass.mu);
    mat.fractureEnergy.push_back(r ? m.G2 : m.G1);
  }
  BondState bonds = makeBondState(c, disc_->neighbours, mat.lambda, mat.mu, mat.fractureEnergy);
  const double left = -0.5 * spec.grid.Lx;
  tipX_ = left + spec.preCrackLength;
  if (spec.preCrackLength > 0)  // from beyond the left edge to the tip, along y = 0
    breakCrossing(bonds, c, disc_->neighbours, {left - 2.0 * c.delta, 0.0, tipX_, 0.0});

  std::vector<double> unit(2 * c.size(), 0.0);
  topCollar_.assign(c.size(), 0);
  const double top = 0.5 * spec.grid.Ly;
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (c.region[p] != Region::Dirichlet) continue;
    const bool isTop = c.y[p] > top - 0.5 * c.h;
    unit[2 * p + 1] = isTop ? 1.0 : -1.0;
    topCollar_[p] = isTop;
  }
  fracture_ = std::make_unique<QuasiStaticFracture>(disc_, std::move(mat), std::move(bonds), std::move(unit),
                                                    spec.linearSolver);
}

LoadStepReport GlassCeramicSpecimen::advance(double UD) { return fracture_->advance(UD); }

std::vector<double> GlassCeramicSpecimen::domainValues(const std::vector<double>& perPoint) const {
  std::vector<double> v;
  v.reserve(disc_->cloud.domain.size());
  for (std::size_t p : disc_->cloud.domain) v.push_back(perPoint[p]);
  return v;
}

std::vector<double> GlassCeramicSpecimen::ux() const {
  std::vector<double> v;
  for (std::size_t p : disc_->cloud.domain) v.push_back(fracture_->displacement()[2 * p]);
  return v;
}
std::vector<double> GlassCeramicSpecimen::uy() const {
  std::vector<double> v;
  for (std::size_t p : disc_->cloud.domain) v.push_back(fracture_->displacement()[2 * p + 1]);
  return v;
}
std::vector<double> GlassCeramicSpecimen::damage() const {
  return damageField(fracture_->bonds(), disc_->cloud, disc_->neighbours);
}
std::vector<double> GlassCeramicSpecimen::youngsModulus() const { return domainValues(E_); }

double GlassCeramicSpecimen::reactionForce() const { return fracture_->collarForce(topCollar_)[1]; }

CrackShares GlassCeramicSpecimen::crackShares() const {
  return peristep::crackShares(disc_->cloud, disc_->neighbours, fracture_->brokenByLoading(), crystal_);
}

double GlassCeramicSpecimen::projectedCrackLength() const {
  const PointCloud& c = disc_->cloud;
  const Neighbours& nb = disc_->neighbours;
  double far = tipX_;
  for (std::size_t k : fracture_->brokenByLoading()) {
    const auto p = static_cast<std::size_t>(std::upper_bound(nb.offset.begin(), nb.offset.end(), k) - nb.offset.begin() - 1);
    far = std::max(far, 0.5 * (c.x[p] + c.x[nb.index[k]]));
  }
  return std::min(far, 0.5 * spec_.grid.Lx) - tipX_;
}

double GlassCeramicSpecimen::energyReleaseRate() const {
  return peristep::energyReleaseRate(crackShares(), projectedCrackLength(), spec_.phases);
}

double GlassCeramicSpecimen::toughnessKIC() const {
  return peristep::toughnessKIC(energyReleaseRate(), fraction_, spec_.phases);
}

bool GlassCeramicSpecimen::crackReachedRightEdge() const {
  return projectedCrackLength() >= 0.5 * spec_.grid.Lx - tipX_ - disc_->cloud.delta;
}

}  // namespace peristep
