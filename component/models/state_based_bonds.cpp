#include "models/state_based_bonds.hpp"

#include <bit>
#include <cmath>
#include <unordered_map>
#include <utility>
#include <string>

#include "core/errors.hpp"
#include "geometry/neighbours.hpp"
#include "models/state_based_potentials.hpp"
#include "quadrature/partial_area.hpp"

namespace peristep {
namespace {

// Appends each bond's direction index to a list, adding its q to the list's table when it is new.
class DirectionTable {
 public:
  explicit DirectionTable(BondList& list) : list_(list) {}
  void add(double qx, double qy) {
    const auto [it, fresh] =
        index_.try_emplace({std::bit_cast<std::uint64_t>(qx), std::bit_cast<std::uint64_t>(qy)},
                           static_cast<std::uint32_t>(list_.q.size() / 2));
    if (fresh) {
      list_.q.push_back(qx);
      list_.q.push_back(qy);
    }
    list_.direction.push_back(it->second);
  }

 private:
  using Bits = std::pair<std::uint64_t, std::uint64_t>;
  struct Hash {
    std::size_t operator()(const Bits& b) const { return std::hash<std::uint64_t>{}(b.first * 0x9e3779b97f4a7c15ULL ^ b.second); }
  };
  BondList& list_;
  std::unordered_map<Bits, std::uint32_t, Hash> index_;
};

}  // namespace

StateBasedBonds buildStateBasedBonds(const PointCloud& cloud, const StateBasedBondOptions& o) {
  const std::size_t n = cloud.size();
  const double h = cloud.h, eps = o.horizon;
  require(n > 0, "state-based bonds: empty point cloud");
  require(std::isfinite(h) && h > 0, "state-based bonds: the cloud has no grid spacing");
  require(std::isfinite(eps) && eps >= h,
          "state-based bonds: horizon must be at least the grid spacing (eps = " + std::to_string(eps) +
              ", h = " + std::to_string(h) + ")");
  require(o.omega.empty() || o.omega.size() == n, "state-based bonds: omega needs one value per point");
  require(o.stiffness.empty() || o.stiffness.size() == n, "state-based bonds: stiffness needs one value per point");

  StateBasedBonds b;
  b.horizon = eps;
  b.cellArea = h * h;
  b.omega = o.omega.empty() ? std::vector<double>(n, 1.0) : o.omega;
  b.kappa = o.stiffness.empty() ? std::vector<double>(n, 1.0) : o.stiffness;
  for (std::size_t p = 0; p < n; ++p) {
    require(b.omega[p] >= 0.0 && b.omega[p] <= 1.0, "state-based bonds: omega must lie in [0, 1]");
    require(std::isfinite(b.kappa[p]) && b.kappa[p] > 0.0, "state-based bonds: stiffness factors must be positive");
  }

  const Neighbours nb = findNeighbours(cloud, eps);
  b.offset.assign(n + 1, 0);
  b.preCrack.offset.assign(n + 1, 0);
  b.neighbour.reserve(nb.bonds());
  b.direction.reserve(nb.bonds());
  for (auto* v : {&b.w, &b.ws}) v->reserve(nb.bonds());
  DirectionTable directions(b), cutDirections(b.preCrack);
  // Void points (a specimen's holes) carry no bonds: they stay where they are and exert nothing.
  const auto isVoid = [&](std::size_t p) { return !cloud.region.empty() && cloud.isVoid(p); };
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = nb.begin(i); k < nb.end(i) && !isVoid(i); ++k) {
      const std::uint32_t j = nb.index[k];
      if (isVoid(j)) continue;
      const double dx = cloud.x[j] - cloud.x[i], dy = cloud.y[j] - cloud.y[i];
      const double L = std::hypot(dx, dy);
      const double J = influenceJ(L / eps);
      if (J <= 1e-12) continue;
      const double base = b.omega[j] * J * b.cellArea * partialAreaFraction(dx, dy, h, eps);
      // Two-point modulus: harmonic mean, as for the LPS model (DESIGN 5.1), so that a bond between a
      // soft and a stiff point is as soft as a series spring.
      const double kij = 2.0 * b.kappa[i] * b.kappa[j] / (b.kappa[i] + b.kappa[j]);
      const double sq = std::sqrt(L);
      const bool cut = bondCrossesAny(cloud.x[i], cloud.y[i], cloud.x[j], cloud.y[j], o.cuts);
      BondList& list = cut ? b.preCrack : b;
      list.neighbour.push_back(j);
      (cut ? cutDirections : directions).add(dx / (L * sq), dy / (L * sq));
      list.w.push_back(kij * base);
      if (!cut) b.ws.push_back(base * sq);
    }
    for (; (b.neighbour.size() - b.offset[i]) % kBondLanes != 0; ++b.padding) {
      b.neighbour.push_back(static_cast<std::uint32_t>(i));
      directions.add(0.0, 0.0);
      for (auto* v : {&b.w, &b.ws}) v->push_back(0.0);
    }
    b.offset[i + 1] = b.neighbour.size();
    b.preCrack.offset[i + 1] = b.preCrack.neighbour.size();
  }
  return b;
}

}  // namespace peristep
