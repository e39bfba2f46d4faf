#include "nested_rules.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gauss_rules.hpp"
#include "patterson_extension.hpp"

namespace peristep::sampling {
namespace {

using detail::Real;
using detail::RealRule;

// Node counts per level. Genz-Keister add 2, 6, 10, 16 nodes: these are counts for which the
// Hermite extension has real nodes (a plain Kronrod extension, 3 -> 7, has not); not extended here
// beyond 35 nodes (degree 51), which is more than the sparse grids of this project use.
// Gauss-Patterson stops at 31: the 63-node extension is too ill-conditioned to pass the check below
// in long double (defect 1.6e-15).
constexpr std::array<int, 5> kPattersonSizes{1, 3, 7, 15, 31};
constexpr std::array<int, 5> kGenzKeisterSizes{1, 3, 9, 19, 35};

int sizeAt(Law law, int level) {
  return law == Law::Uniform ? kPattersonSizes[level] : kGenzKeisterSizes[level];
}

std::vector<Rule1D> buildSequence(Law law) {
  std::vector<Rule1D> levels;
  std::vector<Real> nodes{0};
  levels.push_back(detail::toDouble({nodes, {1}}));
  for (int level = 1; level <= nestedMaxLevel(law); ++level) {
    const int previous = static_cast<int>(nodes.size());
    const std::vector<Real> added = detail::pattersonNodes(law, nodes, sizeAt(law, level) - previous);
    // The earlier nodes are kept bit for bit, so that they round to the same doubles at every level.
    std::vector<Real> merged;
    std::merge(nodes.begin(), nodes.end(), added.begin(), added.end(), std::back_inserter(merged));
    nodes = std::move(merged);
    RealRule rule{nodes, detail::interpolatoryWeights(law, nodes)};
    // Tolerance: a few units of double rounding, which is all the rule keeps once rounded (the 35-node
    // Genz-Keister rule reaches 1.5e-16; the others 2e-18 or less).
    const Real defect = detail::exactnessDefect(law, rule.nodes, rule.weights, nestedRuleDegree(law, level));
    if (!(defect < 1e-15L)) {
      std::ostringstream message;
      message << "nestedRule: level " << level << " is not exact to its degree (defect " << static_cast<double>(defect) << ")";
      throw std::runtime_error(message.str());
    }
    levels.push_back(detail::toDouble(rule));
  }
  return levels;
}

const std::vector<Rule1D>& sequence(Law law) {
  // Built once per law on first use (thread-safe static initialization).
  if (law == Law::Uniform) {
    static const std::vector<Rule1D> uniform = buildSequence(Law::Uniform);
    return uniform;
  }
  static const std::vector<Rule1D> normal = buildSequence(Law::Normal);
  return normal;
}

}  // namespace

int nestedMaxLevel(Law law) {
  return static_cast<int>(law == Law::Uniform ? kPattersonSizes.size() : kGenzKeisterSizes.size()) - 1;
}

int nestedRuleDegree(Law law, int level) {
  if (level < 0 || level > nestedMaxLevel(law))
    throw std::invalid_argument("nestedRuleDegree: level " + std::to_string(level) + " out of range");
  if (level == 0) return 1;
  // m old nodes plus p roots of the maximal-degree extension give degree m + 2p - 1; symmetry adds one.
  const int m = sizeAt(law, level - 1), p = sizeAt(law, level) - m;
  return m + 2 * p;
}

Rule1D nestedRule(Law law, int level) {
  if (level < 0 || level > nestedMaxLevel(law))
    throw std::invalid_argument("nestedRule: level " + std::to_string(level) + " out of range 0.." +
                                std::to_string(nestedMaxLevel(law)));
  return sequence(law)[level];
}

}  // namespace peristep::sampling
