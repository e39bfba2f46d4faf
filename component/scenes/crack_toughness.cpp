#include "scenes/crack_toughness.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace peristep {

CrackToughness::CrackToughness(const QuasiStaticFracture& fracture, double tipX, double tipY, double rightEdge,
                               std::vector<double> G, CrystalField field, PhaseConstants phases)
    : fracture_(&fracture), tipX_(tipX), tipY_(tipY), rightEdge_(rightEdge), G_(std::move(G)),
      field_(std::move(field)), phases_(phases) {}

std::vector<std::size_t> CrackToughness::mainCrackBonds() const {
  const PointCloud& c = fracture_->discretization().cloud;
  const Neighbours& nb = fracture_->discretization().neighbours;
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
    if (std::hypot(mx[i] - tipX_, my[i] - tipY_) <= c.delta) {
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

double CrackToughness::projectedLength(const std::vector<std::size_t>& crack) const {
  const PointCloud& c = fracture_->discretization().cloud;
  const Neighbours& nb = fracture_->discretization().neighbours;
  double far = tipX_;
  for (std::size_t k : crack) far = std::max(far, 0.5 * (c.x[nb.owner(k)] + c.x[nb.index[k]]));
  return std::min(far, rightEdge_) - tipX_;
}

double CrackToughness::centreLength(const std::vector<std::size_t>& crack, double W) const {
  const LpsDiscretization& d = fracture_->discretization();
  return centreLineLength(d.cloud, d.neighbours, crack, tipX_, tipY_, tipX_ + W);
}

double CrackToughness::crackLength() const {
  const std::vector<std::size_t> crack = mainCrackBonds();
  return centreLength(crack, projectedLength(crack));
}

CrackShares CrackToughness::crackShares() const {
  const std::vector<std::size_t> crack = mainCrackBonds();
  return peristep::crackShares(fracture_->discretization().neighbours, crack, field_.crystal,
                               centreLength(crack, projectedLength(crack)));
}

double CrackToughness::projectedCrackLength() const { return projectedLength(mainCrackBonds()); }

double CrackToughness::energyReleaseRate() const {
  const std::vector<std::size_t> crack = mainCrackBonds();
  const double W = projectedLength(crack);
  return W > 0 ? crackEnergy(fracture_->discretization().neighbours, crack, G_, centreLength(crack, W)) / W : 0.0;
}

double CrackToughness::toughnessKIC() const {
  return peristep::toughnessKIC(energyReleaseRate(), field_.fraction, phases_);
}

bool CrackToughness::crackReachedRightEdge() const {
  return projectedCrackLength() >= rightEdge_ - tipX_ - fracture_->discretization().cloud.delta;
}

}  // namespace peristep
