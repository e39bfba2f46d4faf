#include "solvers/gamut_bar_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/errors.hpp"

namespace peristep {

namespace {
constexpr int kMaxIterations = 60;
constexpr int kMaxBisections = 12;
// Modified Newton keeps the old factor while each iteration still cuts the residual by this factor.
constexpr double kFastEnough = 0.1;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::uint8_t kBothElastic = 3;

// K += k g g^T on the lower triangle, g the bond's map from unknowns to elongation.
void addBond(Eigen::MatrixXd& K, const std::array<int, 3>& u, const std::array<double, 3>& c, double k) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (u[i] >= 0 && u[j] >= 0 && u[i] >= u[j]) K(u[i], u[j]) += k * c[i] * c[j];
}
}  // namespace

GamutBarSolver::GamutBarSolver(const GamutBar& bar, double linearStrain)
    : bar_(bar), n_(bar.unknowns()),
      linearStrain_(linearStrain > 0 ? linearStrain : 4 * bar.spec().material.failureStrain),
      linear_(Eigen::MatrixXd::Zero(n_, n_)), u_(Eigen::VectorXd::Zero(n_)), uCommitted_(Eigen::VectorXd::Zero(n_)),
      residual_(Eigen::VectorXd::Zero(n_)) {
  const auto& first = bar.firstElement();
  const auto& k = bar.elementStiffness();
  const auto& cap = bar.elementCap();
  // The nonlocal bonds' elements that may slip, gathered by row (kind, p) in the bar's bond order.
  struct Pair {
    int q;
    long bond;
    double k[2], s[2];
  };
  const std::size_t points = static_cast<std::size_t>(n_) + 1;
  std::vector<std::vector<Pair>> pending(3 * points);
  first_.push_back(0);
  for (std::size_t b = 0; b < bar.bondCount(); ++b) {
    const double l = bar.bondLength()[b];
    const GamutBondPoints where = bar.bondPoints()[b];
    double fixed = 0, active = 0;
    Pair pair{where.q, static_cast<long>(b), {0, 0}, {kInfinity, kInfinity}};
    int slots = 0;
    for (std::size_t e = first[b]; e < first[b + 1]; ++e) {
      if (cap[e] > k[e] * linearStrain_ * l) {
        fixed += k[e];
        continue;
      }
      ++activeElements_;
      active += k[e];
      if (where.kind == GamutBondKind::Local) {
        stiffness_.push_back(k[e]);
        cap_.push_back(cap[e]);
        halfSlip_.push_back(0.5 * cap[e] / k[e]);
      } else {
        require(slots < 2, "gamut bar solver: a nonlocal bond has more than two elements");
        pair.k[slots] = k[e];
        pair.s[slots++] = cap[e] / k[e];
      }
    }
    addBond(linear_, bar.bondUnknowns()[b], bar.bondCoefficients()[b], fixed);
    if (slots > 0) pending[static_cast<std::size_t>(where.kind) * points + static_cast<std::size_t>(where.p)].push_back(pair);
    if (where.kind == GamutBondKind::Local && stiffness_.size() > first_.back()) {
      unknown_.push_back(bar.bondUnknowns()[b]);
      coef_.push_back(bar.bondCoefficients()[b]);
      std::array<int, 3> s = bar.bondUnknowns()[b];
      for (int& i : s) ++i;  // unknown i is point i + 1; no term (-1): point 0, the fixed end
      slot_.push_back(s);
      first_.push_back(stiffness_.size());
      elasticBondTangent_.push_back(active);
    }
  }
  // Rows: the partners q of a row from the first to the last with elements, gaps and the padding to
  // kPairLanes as elements without stiffness that never slip.
  for (std::size_t r = 0; r < pending.size(); ++r) {
    const std::vector<Pair>& pairs = pending[r];
    if (pairs.empty()) continue;
    gamut::PairRow row{static_cast<gamut::PairKind>(r / points), static_cast<int>(r % points), pairs.front().q, kA_.size(), 0};
    const std::size_t span = static_cast<std::size_t>(pairs.back().q - row.qBegin) + 1;
    row.count = (span + gamut::kPairLanes - 1) / gamut::kPairLanes * gamut::kPairLanes;
    const std::size_t size = row.first + row.count;
    kA_.resize(size, 0.0);
    kB_.resize(size, 0.0);
    sA_.resize(size, kInfinity);
    sB_.resize(size, kInfinity);
    pairBond_.resize(size, -1);
    for (const Pair& pair : pairs) {
      const std::size_t j = row.first + static_cast<std::size_t>(pair.q - row.qBegin);
      kA_[j] = pair.k[0];
      kB_[j] = pair.k[1];
      sA_[j] = pair.s[0];
      sB_[j] = pair.s[1];
      pairBond_[j] = pair.bond;
    }
    rows_.push_back(row);
  }
  offsetA_.assign(kA_.size(), 0.0);
  offsetB_.assign(kA_.size(), 0.0);
  trialState_.assign(kA_.size(), kBothElastic);
  tangentState_.assign(kA_.size(), kBothElastic);
  offset_.assign(stiffness_.size(), 0.0);
  padded_ = Eigen::VectorXd::Zero(n_ + 1 + static_cast<int>(gamut::kPairLanes));
  paddedResidual_ = Eigen::VectorXd::Zero(padded_.size());
  bondTangent_ = elasticBondTangent_;
  trialTangent_ = elasticBondTangent_;
  bondSlipping_.assign(unknown_.size(), 0);
  elastic_ = linear_;
  for (std::size_t j = 0; j < pairBond_.size(); ++j)
    if (pairBond_[j] >= 0) addPair(elastic_, j, pairTangent(j, kBothElastic));
  for (std::size_t b = 0; b < unknown_.size(); ++b) addBond(elastic_, unknown_[b], coef_[b], elasticBondTangent_[b]);
  elasticFactor_.compute(elastic_);
  if (elasticFactor_.info() != Eigen::Success) throw SolverFailure("gamut bar: the elastic stiffness matrix is not positive definite");
  ++counters_.factorizations;
  tangent_ = elastic_;
}

void GamutBarSolver::addPair(Eigen::MatrixXd& K, std::size_t j, double k) const {
  const std::size_t b = static_cast<std::size_t>(pairBond_[j]);
  addBond(K, bar_.bondUnknowns()[b], bar_.bondCoefficients()[b], k);
}

void GamutBarSolver::addChangedPairs() {
  // K += dk g g^T for every bond whose elastic bits changed, row by row: a row's entries K(q, p) lie in
  // one column; the diagonal and the row of u_n are gathered by point and added once.
  std::vector<double>& diagonal = diagonalChange_;
  std::vector<double>& last = lastRowChange_;
  diagonal.assign(static_cast<std::size_t>(n_) + 1, 0.0);
  last.assign(static_cast<std::size_t>(n_) + 1, 0.0);
  for (const gamut::PairRow& row : rows_) {
    const int p = row.p;
    for (std::size_t i = 0; i < row.count; ++i) {
      const std::size_t j = row.first + i;
      // Most bonds keep their bits: compare kPairLanes of them at once (rows start at multiples of it).
      if (i % gamut::kPairLanes == 0 &&
          std::memcmp(&trialState_[j], &tangentState_[j], gamut::kPairLanes) == 0) {
        i += gamut::kPairLanes - 1;
        continue;
      }
      if (trialState_[j] == tangentState_[j]) continue;
      const double dk = pairTangent(j, trialState_[j]) - pairTangent(j, tangentState_[j]);
      tangentState_[j] = trialState_[j];
      tangentIsElastic_ = false;
      const int q = row.qBegin + static_cast<int>(i);
      switch (row.kind) {
        case gamut::PairKind::Inside:  // g = e_q - e_p
          diagonal[q] += dk;
          diagonal[p] += dk;
          if (p >= 1) tangent_(q - 1, p - 1) -= dk;
          break;
        case gamut::PairKind::AcrossStart:  // g = e_p + e_q (p >= 1)
          if (q == p) {
            diagonal[p] += 4 * dk;
          } else {
            diagonal[p] += dk;
            diagonal[q] += dk;
            tangent_(q - 1, p - 1) += dk;
          }
          break;
        case gamut::PairKind::AcrossEnd:  // g = 2 e_n - e_p - e_q (q < n)
          diagonal[n_] += 4 * dk;
          if (q == p) {
            diagonal[p] += 4 * dk;
            last[p] -= 4 * dk;
          } else {
            diagonal[p] += dk;
            diagonal[q] += dk;
            last[p] -= 2 * dk;
            last[q] -= 2 * dk;
            if (p >= 1) tangent_(q - 1, p - 1) += dk;
          }
          break;
      }
    }
  }
  // Point 0 is the fixed end: no unknown.
  for (int point = 1; point <= n_; ++point) tangent_(point - 1, point - 1) += diagonal[point];
  for (int point = 1; point < n_; ++point) tangent_(n_ - 1, point - 1) += last[point];
}

void GamutBarSolver::useElasticTangent() {
  if (!tangentIsElastic_) {
    tangent_ = elastic_;
    bondTangent_ = elasticBondTangent_;
    std::fill(tangentState_.begin(), tangentState_.end(), kBothElastic);
    tangentIsElastic_ = true;
  }
  usingElasticFactor_ = true;
  tangentChanged_ = false;
}

void GamutBarSolver::factorize() {
  // The bonds' tangents of the last evaluation go into the matrix only now: most evaluations are
  // followed by a solve with the old factor and need no matrix at all.
  addChangedPairs();
  for (std::size_t b = 0; b < unknown_.size(); ++b)
    if (trialTangent_[b] != bondTangent_[b]) {
      addBond(tangent_, unknown_[b], coef_[b], trialTangent_[b] - bondTangent_[b]);
      bondTangent_[b] = trialTangent_[b];
      tangentIsElastic_ = false;
    }
  // In single precision: the factor only gives Newton directions, the residual is double, and a
  // relative error of 1e-7 times the condition number still converges in as many iterations - until
  // the tangent is so flat (far beyond yield) that it does not; then double precision from there on.
  if (doublePrecision_)
    factorDouble_.compute(tangent_);
  else
    factor_.compute(tangent_);
  ++counters_.factorizations;
  refactor_ = false;
  usingElasticFactor_ = false;
  tangentChanged_ = false;
}

gamut::PairElements GamutBarSolver::pairElements() const {
  return {kA_.data(), kB_.data(), sA_.data(), sB_.data(), offsetA_.data(), offsetB_.data()};
}

double GamutBarSolver::evaluate(double force, bool updateTangent) {
  ++counters_.evaluations;
  const int loaded = bar_.loadedUnknown();
  residual_.noalias() = -(linear_.selfadjointView<Eigen::Lower>() * u_);
  double energy = -0.5 * u_.dot(residual_) - force * u_[loaded];
  residual_[loaded] += force;
  if (updateTangent) tangentChanged_ = false;
  // By point: entry 0 is the fixed end (always 0), so a bond's elongation has no branches.
  padded_.segment(1, n_) = u_;
  paddedResidual_.segment(1, n_) = residual_;
  const double* u = padded_.data();
  double* r = paddedResidual_.data();
  // The nonlocal bonds: the SIMD rows.
  const gamut::PairSums pairs =
      gamut::pairResidual(rows_.data(), rows_.size(), pairElements(), n_, u, r, updateTangent ? trialState_.data() : nullptr);
  energy += pairs.energy;
  slippingPairs_ = pairs.slipping;
  if (updateTangent) tangentChanged_ = trialState_ != tangentState_;
  // The local bonds, element by element.
  for (std::size_t b = 0; b < slot_.size(); ++b) {
    const auto& s = slot_[b];
    const auto& c = coef_[b];
    const double e = c[0] * u[s[0]] + c[1] * u[s[1]] + c[2] * u[s[2]];
    double t = 0, kt = 0;
    bool slipping = false;
    for (std::size_t el = first_[b]; el < first_[b + 1]; ++el) {
      const double stretch = e - offset_[el];
      const double trial = stiffness_[el] * stretch;
      const bool slip = std::abs(trial) > cap_[el];  // slips at its cap: dU/dt = 0, 002:(35)
      t += slip ? std::copysign(cap_[el], trial) : trial;
      kt += slip ? 0.0 : stiffness_[el];
      energy += slip ? cap_[el] * (std::abs(stretch) - halfSlip_[el]) : 0.5 * trial * stretch;
      slipping |= slip;
    }
    bondSlipping_[b] = slipping;
    if (updateTangent) {
      trialTangent_[b] = kt;
      tangentChanged_ |= kt != bondTangent_[b];
    }
    r[s[0]] -= c[0] * t;
    r[s[1]] -= c[1] * t;
    r[s[2]] -= c[2] * t;
  }
  residual_ = paddedResidual_.segment(1, n_);
  energy_ = energy;
  return residual_.lpNorm<Eigen::Infinity>();
}

bool GamutBarSolver::solveTo(double force) {
  // On a reversal every slipping element reloads elastically: start from the elastic tangent.
  if ((force - force_) * lastIncrement_ <= 0) useElasticTangent();
  // The step minimizes Pi(u) = sum of the elements' energies (from the committed offsets) - F u_n,
  // convex and C1: Newton directions of any positive definite tangent with a backtracking (Armijo)
  // line search converge.
  u_ = uCommitted_;
  // Residual below 1e-9 of the larger end force of the step: a relative strain error of that order.
  const double tolerance = 1e-9 * std::max(std::abs(force), std::abs(force_));
  double r = evaluate(force, false);
  double previous = std::numeric_limits<double>::infinity();
  Eigen::VectorXd direction, base;
  for (int it = 0; it < kMaxIterations; ++it) {
    ++counters_.iterations;
    if (!std::isfinite(r)) return false;
    if (r <= tolerance) return true;
    if (refactor_ || (tangentChanged_ && !(r < kFastEnough * previous))) {
      factorize();
      if ((doublePrecision_ ? factorDouble_.info() : factor_.info()) != Eigen::Success)
        useElasticTangent();  // the elastic tangent is always definite
    }
    previous = r;
    if (usingElasticFactor_)
      direction = elasticFactor_.solve(residual_);
    else if (doublePrecision_)
      direction = factorDouble_.solve(residual_);
    else
      direction = factor_.solve(residual_.cast<float>()).cast<double>();
    const double slope = direction.dot(residual_), start = energy_;
    base = u_;
    for (double alpha = 1;;) {
      u_ = base + alpha * direction;
      r = evaluate(force, true);
      // Armijo, with room for the rounding of Pi near convergence.
      if (energy_ <= start - 1e-4 * alpha * slope + 1e-13 * (std::abs(start) + slope)) break;
      if (alpha < 1e-6) return false;
      // Pi is convex along the line: the secant of its slope (-slope at 0, -residual . direction at
      // alpha) locates the minimum; kept within [alpha / 10, alpha / 2].
      const double end = -direction.dot(residual_);
      alpha *= std::clamp(slope / (slope + std::max(end, 0.0)), 0.1, 0.5);
    }
  }
  return false;
}

void GamutBarSolver::commit(double force) {
  // The elements summed into linear_ stay elastic while no local bond strains beyond linearStrain_.
  const auto& x = bar_.positions();
  double previous = 0;
  for (int j = 0; j < n_; ++j) {
    if (std::abs(u_[j] - previous) > linearStrain_ * (x[j + 1] - x[j]))
      throw LinearRangeExceeded("gamut bar: a local strain passed " + std::to_string(linearStrain_) +
                                ", the bound below which the far elements were taken as elastic");
    previous = u_[j];
  }
  padded_.segment(1, n_) = u_;
  const double* u = padded_.data();
  gamut::pairCommit(rows_.data(), rows_.size(), sA_.data(), sB_.data(), offsetA_.data(), offsetB_.data(), n_, u);
  for (std::size_t b = 0; b < slot_.size(); ++b) {
    const auto& s = slot_[b];
    const auto& c = coef_[b];
    const double e = c[0] * u[s[0]] + c[1] * u[s[1]] + c[2] * u[s[2]];
    for (std::size_t el = first_[b]; el < first_[b + 1]; ++el) {
      const double trial = stiffness_[el] * (e - offset_[el]);
      if (std::abs(trial) > cap_[el]) offset_[el] = e - std::copysign(cap_[el], trial) / stiffness_[el];
    }
  }
  uCommitted_ = u_;
  lastIncrement_ = force - force_;
  force_ = force;
}

GamutBarOutput GamutBarSolver::step(double force) {
  // Bisection of the increment when Newton does not converge (active sets cycling on a long step).
  std::vector<double> targets{force};
  int depth = 0;
  while (!targets.empty()) {
    const double target = targets.back();
    if (solveTo(target)) {
      commit(target);
      targets.pop_back();
    } else if (!doublePrecision_) {
      doublePrecision_ = refactor_ = true;  // first try the same step with a double-precision factor
    } else {
      if (++depth > kMaxBisections)
        throw SolverFailure("gamut bar: no equilibrium at an end force of " + std::to_string(force) + " N");
      targets.push_back(0.5 * (force_ + target));
      ++counters_.substeps;
    }
  }
  ++counters_.steps;
  GamutBarOutput out;
  out.stress = force_ / bar_.spec().area;
  out.strain = uCommitted_[bar_.loadedUnknown()] / bar_.spec().length;
  out.brokenBonds = slippingPairs_;
  for (unsigned char s : bondSlipping_) out.brokenBonds += s;
  return out;
}

}  // namespace peristep
