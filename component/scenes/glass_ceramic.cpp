#include "scenes/glass_ceramic.hpp"

#include <algorithm>
#include <cmath>
#include <map>

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

  std::vector<double> R = spec.crystalField;
  if (R.empty()) {
    crystal_ = generateMicrostructure(c, spec.crystalFraction, spec.seed);
    R.assign(crystal_.begin(), crystal_.end());
    fraction_ = crystalFraction(c, crystal_);
  } else {
    require(R.size() == c.size(), "crystal field has " + std::to_string(R.size()) + " values for " +
                                      std::to_string(c.size()) + " points");
    crystal_.clear();
    fraction_ = 0;
    for (double r : R) crystal_.push_back(r >= 0.5);
    for (std::size_t p : c.domain) fraction_ += R[p] / static_cast<double>(c.domain.size());
  }
  FractureMaterial mat;
  for (std::size_t p = 0; p < c.size(); ++p) {  // 000:(5.5): E and G affine in R
    const double E = m.E1 + R[p] * (m.E2 - m.E1), G = m.G1 + R[p] * (m.G2 - m.G1);
    if (!(E > 0 && G > 0))
      throw InvalidInput("crystal field R = " + std::to_string(R[p]) + " at (x, y) = (" + std::to_string(c.x[p]) +
                         ", " + std::to_string(c.y[p]) + ") gives E = " + std::to_string(E) + " Pa, G = " +
                         std::to_string(G) + " J/m^2: not positive (a coordinate too far in the tail)");
    const Lame l = planeStrain(E, m.nu);
    E_.push_back(E);
    G_.push_back(G);
    mat.lambda.push_back(l.lambda);
    mat.mu.push_back(l.mu);
    mat.fractureEnergy.push_back(G);
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
                                                    spec.linearSolver, spec.reuse, spec.zonePrecision);
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

std::vector<std::size_t> GlassCeramicSpecimen::mainCrackBonds() const {
  const PointCloud& c = disc_->cloud;
  const Neighbours& nb = disc_->neighbours;
  const std::vector<std::size_t>& broken = fracture_->brokenByLoading();
  std::vector<double> mx(broken.size()), my(broken.size());
  for (std::size_t i = 0; i < broken.size(); ++i) {
    const std::size_t p = nb.owner(broken[i]), q = nb.index[broken[i]];
    mx[i] = 0.5 * (c.x[p] + c.x[q]);
    my[i] = 0.5 * (c.y[p] + c.y[q]);
  }
  // Breadth-first search over midpoints, with the midpoints binned in cells of the link length so
  // that only the 3 x 3 cells around a midpoint are searched (full size: ~1e4 broken pairs).
  const double link = 1.5 * c.h, link2 = link * link;
  const auto cellOf = [&](std::size_t i) {
    return std::pair{static_cast<long>(std::floor(mx[i] / link)), static_cast<long>(std::floor(my[i] / link))};
  };
  std::map<std::pair<long, long>, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < broken.size(); ++i) cells[cellOf(i)].push_back(i);
  std::vector<char> reached(broken.size(), 0);
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < broken.size(); ++i)
    if (std::hypot(mx[i] - tipX_, my[i]) <= c.delta) {
      reached[i] = 1;
      queue.push_back(i);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t i = queue[head];
    const auto [cx, cy] = cellOf(i);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const auto cell = cells.find({cx + dx, cy + dy});
        if (cell == cells.end()) continue;
        for (std::size_t j : cell->second)
          if (!reached[j] && (mx[j] - mx[i]) * (mx[j] - mx[i]) + (my[j] - my[i]) * (my[j] - my[i]) <= link2) {
            reached[j] = 1;
            queue.push_back(j);
          }
      }
  }
  std::vector<std::size_t> main;
  for (std::size_t i = 0; i < broken.size(); ++i)
    if (reached[i]) main.push_back(broken[i]);
  return main;
}

double GlassCeramicSpecimen::projectedLength(const std::vector<std::size_t>& crack) const {
  const PointCloud& c = disc_->cloud;
  const Neighbours& nb = disc_->neighbours;
  double far = tipX_;
  for (std::size_t k : crack) far = std::max(far, 0.5 * (c.x[nb.owner(k)] + c.x[nb.index[k]]));
  return std::min(far, 0.5 * spec_.grid.Lx) - tipX_;
}

double GlassCeramicSpecimen::centreLength(const std::vector<std::size_t>& crack, double W) const {
  return centreLineLength(disc_->cloud, disc_->neighbours, crack, tipX_, 0.0, tipX_ + W);
}

double GlassCeramicSpecimen::crackLength() const {
  const std::vector<std::size_t> crack = mainCrackBonds();
  return centreLength(crack, projectedLength(crack));
}

CrackShares GlassCeramicSpecimen::crackShares() const {
  const std::vector<std::size_t> crack = mainCrackBonds();
  return peristep::crackShares(disc_->neighbours, crack, crystal_, centreLength(crack, projectedLength(crack)));
}

double GlassCeramicSpecimen::projectedCrackLength() const { return projectedLength(mainCrackBonds()); }

double GlassCeramicSpecimen::energyReleaseRate() const {
  const std::vector<std::size_t> crack = mainCrackBonds();
  const double W = projectedLength(crack);
  return W > 0 ? crackEnergy(disc_->neighbours, crack, G_, centreLength(crack, W)) / W : 0.0;
}

double GlassCeramicSpecimen::toughnessKIC() const {
  return peristep::toughnessKIC(energyReleaseRate(), fraction_, spec_.phases);
}

bool GlassCeramicSpecimen::crackReachedRightEdge() const {
  return projectedCrackLength() >= 0.5 * spec_.grid.Lx - tipX_ - disc_->cloud.delta;
}

}  // namespace peristep
