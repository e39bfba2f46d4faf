#include "models/gamut_bar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "core/errors.hpp"
#include "geometry/bar_grid.hpp"
#include "models/gamut_local_bonds.hpp"
#include "models/gamut_weights.hpp"

namespace peristep {

namespace {

// Where a point's nonlocal partner q lies: in the bar, or in its mirror image beyond x = 0 or x = L.
enum Side : int { Inside = 0, BeyondStart = 1, BeyondEnd = 2 };

void validate(const GamutBarSpec& s) {
  const RambergOsgood& m = s.material;
  require(m.youngsModulus > 0 && m.yieldStress > 0 && m.failureStress > 0 && m.failureStrain > 0 && m.exponent > 1 &&
              m.yieldOffset > 0,
          "gamut bar: E, sigma_y, sigma_f, eps_f, K_ro must be positive and n_ro > 1");
  require(s.length > 0 && s.area > 0, "gamut bar: length and area must be positive");
  require(s.bonds >= 4, "gamut bar: needs at least 4 local bonds (nonlocal partners on both sides)");
  require(s.scatter.denominator > 0 && s.scatter.weibullScale > 0 && s.scatter.weibullShape > 0,
          "gamut bar: Weibull scale, shape and the scatter denominator must be positive");
  require(s.weightCutoff >= 0 && s.weightCutoff < 1e-6, "gamut bar: the weight cutoff must lie in [0, 1e-6)");
}

}  // namespace

// Per point and partner (side, q): the normalized weight and the critical strain of the point's element.
struct GamutBar::PartnerTable {
  explicit PartnerTable(std::size_t points) : points(points), weight(3 * points * points, 0.0), strain(3 * points * points, 0.0) {}
  std::size_t at(std::size_t p, int side, std::size_t q) const { return (static_cast<std::size_t>(side) * points + p) * points + q; }
  std::size_t points;
  std::vector<double> weight, strain;
};

GamutBar::GamutBar(const GamutBarSpec& spec, std::uint64_t realization) : spec_(spec) {
  validate(spec);
  ScatterStream stream(spec.seed, realization);
  x_ = barGrid(spec.length, spec.bonds, spec.gridJitter, stream);
  const std::vector<double> softness = drawProperties(stream);
  const PartnerTable table = slipLadders(stream);
  firstElement_.push_back(0);  // bond b's elements are [firstElement_[b], firstElement_[b + 1])
  addLocalBonds(addNonlocalBonds(table, softness));
}

// Point properties: E by 002:(26) into modulus_; returns R from 002:(30) with the point's E, then
// scattered by (26) itself.
std::vector<double> GamutBar::drawProperties(ScatterStream& stream) {
  const GamutBarSpec& spec = spec_;
  const std::size_t points = x_.size();
  modulus_.resize(points);
  std::vector<double> softness(points);
  for (double& E : modulus_) E = spec.material.youngsModulus * (spec.scatterProperties ? stream.positiveFactor(spec.scatter) : 1.0);
  // 002 says R lies in [0, 1] (Sec. 2); a draw outside (0, 1) is drawn again, as 002 Sec. 4.3 draws a
  // grid again when points overlap.
  for (std::size_t p = 0; p < points; ++p) {
    const double mean = spec.material.softness(modulus_[p]);
    require(mean > 0 && mean < 1, "gamut bar: the material's modulus of softness R of 002:(30) lies outside (0, 1)");
    double R = mean;
    if (spec.scatterProperties)
      do R = mean * (1.0 + stream.relativeScatter(spec.scatter));
      while (R >= 1 || R <= 0);
    softness[p] = R;
  }
  return softness;
}

// Weights and the ladder of critical strains, point by point.
GamutBar::PartnerTable GamutBar::slipLadders(ScatterStream& stream) const {
  const GamutBarSpec& spec = spec_;
  const std::size_t points = x_.size(), n = points - 1;
  const double L = spec.length;
  PartnerTable table(points);
  std::vector<std::tuple<double, int, std::size_t>> partners;  // (distance, side, q)
  std::vector<double> distance, weight;
  std::vector<std::size_t> order;
  for (std::size_t p = 0; p < points; ++p) {
    partners.clear();
    double nearest = L;
    // Nonlocal: two or more degrees of separation on the mirrored grid (..., 2~, 1~, 0, 1, ..., n, (n-1)^, ...).
    // The partners in four runs, each already in increasing distance (the grid increases, and rounding
    // keeps x_q - x_p, x_p + x_q and (2L - x_p) - x_q monotone in x_q), merged: the same order as sorting
    // them all, since no two (distance, side, q) are equal.
    auto inside = [&](std::size_t q) {
      const double l = std::abs(x_[q] - x_[p]);
      partners.emplace_back(l, Inside, q);
      nearest = std::min(nearest, l);
    };
    for (std::size_t q = p >= 2 ? p - 1 : 0; q-- > 0;) inside(q);  // q = p - 2 .. 0
    const std::size_t left = partners.size();
    for (std::size_t q = p + 2; q < points; ++q) inside(q);
    const std::size_t right = partners.size();
    for (std::size_t q = 1; q < points; ++q)
      if (p + q >= 2) partners.emplace_back(x_[p] + x_[q], BeyondStart, q);
    const std::size_t start = partners.size();
    for (std::size_t q = n; q-- > 0;)  // q = n - 1 .. 0
      if (2 * n - p - q >= 2) partners.emplace_back(2 * L - x_[p] - x_[q], BeyondEnd, q);
    const auto first = partners.begin();
    std::inplace_merge(first, first + static_cast<std::ptrdiff_t>(left), first + static_cast<std::ptrdiff_t>(right));
    std::inplace_merge(first + static_cast<std::ptrdiff_t>(right), first + static_cast<std::ptrdiff_t>(start), partners.end());
    std::inplace_merge(first, first + static_cast<std::ptrdiff_t>(right), partners.end());
    distance.resize(partners.size());
    weight.resize(partners.size());
    for (std::size_t i = 0; i < partners.size(); ++i) distance[i] = std::get<0>(partners[i]);
    // 002:(31) with the farthest nonlocal point at the distance L: with the mirror images every point's
    // nonlocal domain reaches L or farther (the farthest point of the bar alone would make sigma twice as
    // large at the ends as in the middle, and the ends of a homogeneous bar would not carry its load
    // like its middle).
    calibratedWeights(distance, interactionLength(nearest, L), spec.scatterProperties ? &stream : nullptr,
                      spec.scatter, weight);

    RambergOsgood own = spec.material;
    own.youngsModulus = modulus_[p];
    const double E = own.youngsModulus;
    // The point's nonlocal elements carry R of its stiffness (002:(B.5)) and slip in the order of their
    // weights, the heaviest (nearest) first, so that the weight sets the critical deformation (002
    // Sec. 2) and the many light elements resolve the flat end of the curve where the cyclic amplitudes
    // lie. A group of elements slips when the point's tangent modulus has fallen to
    // E (S_before + S_after) / 2, S being the share of its nonlocal elements still elastic.
    auto slipStrain = [&](double after, double share) { return own.strain(own.stressAtTangent(E * (after + 0.5 * share))); };
    order.resize(partners.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return weight[a] < weight[b]; });
    // Equal weights (a partner on each side at the same distance) are one group with one critical strain.
    double lighter = 0;  // share of the groups that slip after this one
    for (std::size_t g = 0; g < order.size();) {
      std::size_t end = g;
      double share = 0;
      while (end < order.size() && weight[order[end]] <= weight[order[g]] * (1 + 1e-9)) share += weight[order[end++]];
      const double strain = weight[order[g]] >= spec.weightCutoff ? slipStrain(lighter, share) : 0.0;
      lighter += share;
      for (; g < end; ++g) {
        const std::size_t i = order[g];
        const std::size_t at = table.at(p, std::get<1>(partners[i]), std::get<2>(partners[i]));
        table.weight[at] = weight[i];
        table.strain[at] = strain;
      }
    }
  }
  return table;
}

void GamutBar::addElement(double k, double strain, double l) {
  stiffness_.push_back(k);
  cap_.push_back(k * strain * l);
}

// Closes the bond whose elements were added since the last one: u_bond = sum coefs[k] u_(nodes[k]) (node 0
// is fixed, -1 unused). False, and nothing added, when it has no element.
bool GamutBar::closeBond(std::array<int, 3> nodes, std::array<double, 3> coefs, double l, GamutBondKind kind,
                         std::size_t p, std::size_t q) {
  if (stiffness_.size() == firstElement_.back()) return false;
  std::array<int, 3> u{-1, -1, -1};
  std::array<double, 3> c{0, 0, 0};
  int terms = 0;
  for (int k = 0; k < 3; ++k) {
    if (nodes[k] <= 0 || coefs[k] == 0) continue;  // node 0 is fixed
    const int unknown = nodes[k] - 1;
    int slot = 0;
    while (slot < terms && u[slot] != unknown) ++slot;
    if (slot == terms) u[terms++] = unknown;
    c[slot] += coefs[k];
  }
  unknown_.push_back(u);
  coef_.push_back(c);
  length_.push_back(l);
  points_.push_back({kind, static_cast<int>(p), static_cast<int>(q)});
  firstElement_.push_back(stiffness_.size());
  return true;
}

// The nonlocal bonds, inside the bar and across its mirrored ends; returns the cuts each crosses.
std::vector<CutCrossing> GamutBar::addNonlocalBonds(const PartnerTable& table, const std::vector<double>& softness) {
  const std::size_t points = x_.size(), n = points - 1;
  const double L = spec_.length, A = spec_.area;
  // Length of a point's local volume (mirrored at the ends).
  std::vector<double> cell(points);
  for (std::size_t p = 0; p < points; ++p) {
    const double left = p > 0 ? x_[p] - x_[p - 1] : x_[1] - x_[0];
    const double right = p < n ? x_[p + 1] - x_[p] : x_[n] - x_[n - 1];
    cell[p] = 0.5 * (left + right);
  }
  // Nonlocal element of owner o on a bond of length l: U_NL = w R U_L (002:(24)) under a uniform strain.
  auto addNonlocal = [&](std::size_t o, int side, std::size_t q, double l) {
    const std::size_t at = table.at(o, side, q);
    if (table.weight[at] >= spec_.weightCutoff)
      addElement(table.weight[at] * softness[o] * A * modulus_[o] * cell[o] / (l * l), table.strain[at], l);
  };
  std::vector<CutCrossing> crossings;  // cuts j (between points j and j + 1) crossed by each bond
  auto cross = [&](std::size_t first, std::size_t end, double multiplicity) {
    if (first < end) crossings.push_back({bondCount() - 1, first, end, multiplicity});
  };
  const int last = static_cast<int>(n);
  for (std::size_t p = 0; p < points; ++p)
    for (std::size_t q = p + 2; q < points; ++q) {
      const double l = x_[q] - x_[p];
      addNonlocal(p, Inside, q, l);
      addNonlocal(q, Inside, p, l);
      if (closeBond({static_cast<int>(q), static_cast<int>(p), -1}, {1, -1, 0}, l, GamutBondKind::Inside, p, q)) cross(p, q, 1);
    }
  // Across x = 0: u(-x_q) = -u_q. The pair stands for the bonds p-q~ and q-p~ of the mirrored bar
  // (one bond, p~-p, when q = p), each crossing the cuts between x = 0 and its real end.
  for (std::size_t p = 1; p < points; ++p)
    for (std::size_t q = p; q < points; ++q) {
      const double l = x_[p] + x_[q];
      addNonlocal(p, BeyondStart, q, l);
      if (q != p) addNonlocal(q, BeyondStart, p, l);
      if (closeBond({static_cast<int>(p), static_cast<int>(q), -1}, {1, 1, 0}, l, GamutBondKind::AcrossStart, p, q)) {
        cross(0, p, q == p ? 2 : 1);
        if (q != p) cross(0, q, 1);
      }
    }
  for (std::size_t p = 0; p < n; ++p)  // across x = L: u(2L - x_q) = 2 u_n - u_q
    for (std::size_t q = p; q < n; ++q) {
      const double l = 2 * L - x_[p] - x_[q];
      addNonlocal(p, BeyondEnd, q, l);
      if (q != p) addNonlocal(q, BeyondEnd, p, l);
      if (closeBond({last, static_cast<int>(p), static_cast<int>(q)}, {2, -1, -1}, l, GamutBondKind::AcrossEnd, p, q)) {
        cross(p, n, q == p ? 2 : 1);
        if (q != p) cross(q, n, 1);
      }
    }
  return crossings;
}

// Local bonds (002:(28)): each takes what the nonlocal elements leave of A sigma_RO(eps) at its cut.
void GamutBar::addLocalBonds(const std::vector<CutCrossing>& crossings) {
  const GamutBarSpec& spec = spec_;
  const std::size_t n = x_.size() - 1;
  const std::vector<double> knots = localKnots(spec.material.yieldStress / spec.material.youngsModulus + spec.material.yieldOffset,
                                               spec.material.failureStrain);
  const std::size_t m = knots.size();
  const std::vector<double> nonlocal = nonlocalCutForces(crossings, firstElement_, stiffness_, cap_, length_, knots, n);
  std::vector<double> remainder(m);
  for (std::size_t j = 0; j < n; ++j) {
    RambergOsgood own = spec.material;
    own.youngsModulus = modulus_[j];
    for (std::size_t k = 0; k < m; ++k) remainder[k] = spec.area * own.stress(knots[k]) - nonlocal[j * m + k];
    const LocalBundle bundle = localBundle(knots, remainder);
    const double l = x_[j + 1] - x_[j];
    for (std::size_t e = 0; e < bundle.stiffness.size(); ++e)
      if (bundle.stiffness[e] > 0) addElement(bundle.stiffness[e] / l, bundle.strain[e], l);
    closeBond({static_cast<int>(j + 1), static_cast<int>(j), -1}, {1, -1, 0}, l, GamutBondKind::Local, j, j + 1);
  }
}

}  // namespace peristep
