#include "solvers/quasi_static_fracture.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"
#include "core/timer.hpp"
#include "linalg/gmres.hpp"
#include "models/collar_force.hpp"
#include "models/lps_material.hpp"

namespace peristep {
namespace {

// Relative stiffness of the springs that hold points with broken bonds near their last position. They
// remove the rigid-body modes of floating fragments and the mechanisms of nearly detached points
// (no singular factorization, no NaN) and perturb the solution by about this relative amount.
constexpr double kSpringRatio = 1e-8;
constexpr int kMaxSubIterations = 100000;
// GMRES stops at this relative residual. The springs make the matrix ill-conditioned, and 1e-10 was not
// enough: at h = 8 um it gave another crack history than a direct solve of every changed matrix;
// 1e-13 gives the same history (docs/decisions/0003-crack-zone-driver.md) for about 10% more iterations.
constexpr double kKrylovTolerance = 1e-13;
constexpr int kKrylovRestart = 40;
// GMRES directions kept for a zone's later solves. Each Arnoldi step reads them twice: with all of a zone's (up to
// its price, 50 at h = 2 um) the full size ran 2% slower than without, with 16 4% faster
// (docs/decisions/0002-recycled-gmres.md).
constexpr std::size_t kKeptDirections = 16;
// A sub-iteration may decide its breaks on a solution refined only to this backward error, when no bond's stretch
// lies within the error bound of its s0. The bound is this multiple of the last correction's largest displacement
// change: the error left was at most 6.4e-6 of it in 599 such solves at h = 8 and 4 um
// (docs/decisions/0009-settled-verdicts.md). GMRES solves refine to tolerance: the step of their last iteration
// bounded the error only to 4e-2.
constexpr double kSettleTolerance = 1e-6;
constexpr double kErrorPerChange = 1e-3;
// GMRES iterations allowed where refinement with single-precision zone factors diverged.
constexpr int kRescueIterations = 200;
// The crack zone: points whose bonds reach this fraction of their critical stretch, the closest first,
// up to this many unknowns in the dense Schur complement (docs/decisions/0003-crack-zone-driver.md).
constexpr double kZoneRatio = 0.1;
constexpr std::size_t kZoneUnknowns = 3000, kZoneShare = 10;  // at most a tenth of the unknowns
// A point whose u block has an eigenvalue below this fraction of its largest hangs by its spring in one
// direction (measured at the fall-backs: 3e-8 to 3e-7, next 1.9e-2); such points join the zone.
constexpr double kNearlyFloatingRatio = 1e-4;

// A numeric factorization priced in preconditioned GMRES iterations (one solve with the factors and one
// product with A each). Measured with UMFPACK+METIS on glass-ceramic matrices of 16k and 62k unknowns
// (docs/decisions/0003-crack-zone-driver.md): 28 and 33 solves per factorization, about 2.2 n^(1/4). A
// count, not a clock, so that the solver's choices, and with them the run, never depend on the load of
// the machine.
int factorizationCostInIterations(std::int64_t unknowns) {
  return std::max(2, static_cast<int>(std::lround(2.2 * std::pow(static_cast<double>(unknowns), 0.25))));
}

double springStiffness(double mu, double delta) { return kSpringRatio * 24.0 * mu / (delta * delta); }

}  // namespace

QuasiStaticFracture::QuasiStaticFracture(std::shared_ptr<const LpsDiscretization> disc, FractureMaterial material,
                                         BondState bonds, std::vector<double> unitCollarDisplacement,
                                         LinearSolverKind solver, FactorizationReuse reuse,
                                         FactorPrecision zonePrecision)
    : disc_(std::move(disc)),
      material_(std::move(material)),
      bonds_(std::move(bonds)),
      unitCollar_(std::move(unitCollarDisplacement)),
      reuse_(reuse) {
  const std::size_t n = disc_->cloud.size();
  require(material_.lambda.size() == n && material_.mu.size() == n && material_.fractureEnergy.size() == n,
          "fracture material must have one value per point");
  require(unitCollar_.size() == 2 * n, "collar displacement must have two components per point");
  require(bonds_.bonds() == disc_->neighbours.bonds(), "bond state does not match the neighbour lists");
  u_.assign(2 * n, 0.0);
  x_.assign(static_cast<std::size_t>(disc_->dofs.size), 0.0);
  factorizationCost_ = factorizationCostInIterations(disc_->dofs.size);
  assemble(nullptr);
  if (reuse_ == FactorizationReuse::CrackZone) {
    zone_ = std::make_unique<CrackZoneSolver>(disc_->neighbours, disc_->dofs, zonePrecision, kKeptDirections);
    return;
  }
  solver_ = makeLinearSolver(solver);
  // The symbolic analysis belongs to the matrix of the construction state in every instance (UMFPACK's
  // strategy looks at the values), so that a state restored into another instance factors identically.
  solver_->analyze(system_.A);
}

LpsSystem QuasiStaticFracture::assembleFor(const std::vector<std::uint8_t>& intact,
                                           std::vector<std::uint8_t>& stabilized) const {
  const PointCloud& c = disc_->cloud;
  const Neighbours& nb = disc_->neighbours;
  LpsSystem s = assembleLps(c, nb, disc_->weights, material_.lambda, material_.mu, disc_->dofs, &intact);
  stabilized.assign(c.size(), 0);
  for (std::size_t p : c.domain)
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k)
      if (!intact[k]) stabilized[p] = 1;
  addSprings(s, c.domain, stabilized);
  return s;
}

void QuasiStaticFracture::addSprings(LpsSystem& s, std::span<const std::size_t> points,
                                     const std::vector<std::uint8_t>& stabilized) const {
  for (std::size_t p : points) {
    if (!stabilized[p] || disc_->dofs.u[p] < 0) continue;
    const double spring = springStiffness(material_.mu[p], disc_->cloud.delta);
    for (int a = 0; a < 2; ++a) {
      const std::int64_t row = disc_->dofs.u[p] + a;
      for (std::int64_t k = s.A.rowStart[row]; k < s.A.rowStart[row + 1]; ++k)
        if (s.A.col[k] == row) s.A.value[k] += spring;
    }
  }
}

void QuasiStaticFracture::reassembleAround(const std::vector<std::size_t>& fresh, LoadStepReport& report) {
  // Breaking p-q changes the rows of p and q (their bonds, the frames of 000:(3.20)-(3.22), the springs)
  // and of the points within delta of both (the free-surface test looks two bonds deep): all in
  // {p} + N(p) + {q}.
  Stopwatch clock;
  const Neighbours& nb = disc_->neighbours;
  std::vector<std::uint8_t> mark(disc_->cloud.size(), 0);
  for (std::size_t k : fresh) {
    const std::size_t p = nb.owner(k);
    mark[p] = mark[nb.index[k]] = 1;
    for (std::size_t j = nb.begin(p); j < nb.end(p); ++j) mark[nb.index[j]] = 1;
  }
  std::vector<std::size_t> points;
  for (std::size_t p = 0; p < mark.size(); ++p)
    if (mark[p]) points.push_back(p);
  for (std::size_t p : points)
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k)
      if (!bonds_.intact[k] && disc_->cloud.inDomain(p)) stabilized_[p] = 1;
  reassembleLpsRows(disc_->cloud, nb, disc_->weights, material_.lambda, material_.mu, disc_->dofs, bonds_.intact,
                    points, system_);
  addSprings(system_, points, stabilized_);
  std::vector<std::size_t> merged;
  std::set_union(dirty_.begin(), dirty_.end(), points.begin(), points.end(), std::back_inserter(merged));
  dirty_ = std::move(merged);
  matrixFactored_ = false;
  report.assemblySeconds += clock.seconds();
}

void QuasiStaticFracture::assemble(LoadStepReport* report) {
  Stopwatch clock;
  system_ = assembleFor(bonds_.intact, stabilized_);
  matrixFactored_ = false;
  if (report) report->assemblySeconds += clock.seconds();
}

void QuasiStaticFracture::factorizeCurrent(LoadStepReport& report) {
  Stopwatch clock;
  factoredA_ = system_.A;  // the solver keeps a pointer to the matrix it factorized
  solver_->factorize(factoredA_);
  factoredBroken_ = brokenByLoading_.size();
  hasFactorization_ = factorizationLive_ = matrixFactored_ = true;
  staleIterations_ = lastKrylovIterations_ = 0;
  ++report.factorizations;
  report.factorizationSeconds += clock.seconds();
}

void QuasiStaticFracture::rebuildFactorization(LoadStepReport& report) {
  // After a restore: factorize the matrix of the recorded state again (the current bonds with those
  // broken since then still intact); the policy counters were restored with the state.
  Stopwatch clock;
  std::vector<std::uint8_t> unused;
  factoredA_ = factoredBroken_ == brokenByLoading_.size() ? system_.A : assembleFor(intactAt(factoredBroken_), unused).A;
  solver_->factorize(factoredA_);
  factorizationLive_ = true;
  ++report.factorizations;
  report.factorizationSeconds += clock.seconds();
}

void QuasiStaticFracture::solveCurrent(LoadStepReport& report) {
  const PointCloud& c = disc_->cloud;
  const DofMap& d = disc_->dofs;
  std::vector<double> g(unitCollar_.size());
  for (std::size_t k = 0; k < g.size(); ++k) g[k] = load_ * unitCollar_[k];
  rhs_.assign(x_.size(), 0.0);
  system_.B.multiply(g, rhs_);
  for (double& v : rhs_) v = -v;
  for (std::size_t p : c.domain)
    if (stabilized_[p])
      for (int a = 0; a < 2; ++a)
        rhs_[static_cast<std::size_t>(d.u[p] + a)] +=
            springStiffness(material_.mu[p], c.delta) * u_[2 * p + static_cast<std::size_t>(a)];

  settledChange_ = 0;
  if (reuse_ == FactorizationReuse::CrackZone) {
    solveInZone(rhs_, report, true);
  } else {
    solveWithFactorization(rhs_, report);
  }
  takeSolution();
}

void QuasiStaticFracture::finishSolve(LoadStepReport& report) {
  settledChange_ = 0;
  solveInZone(rhs_, report, false);
  takeSolution();
}

void QuasiStaticFracture::takeSolution() {
  const PointCloud& c = disc_->cloud;
  const DofMap& d = disc_->dofs;
  for (double v : x_)
    if (!std::isfinite(v)) throw SolverFailure("fracture solve produced a non-finite displacement");
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (d.u[p] >= 0) {
      u_[2 * p] = x_[static_cast<std::size_t>(d.u[p])];
      u_[2 * p + 1] = x_[static_cast<std::size_t>(d.u[p]) + 1];
    } else {
      u_[2 * p] = c.isVoid(p) ? 0.0 : load_ * unitCollar_[2 * p];
      u_[2 * p + 1] = c.isVoid(p) ? 0.0 : load_ * unitCollar_[2 * p + 1];
    }
  }
}

bool QuasiStaticFracture::iterateWithinBudget(LoadStepReport& report,
                                              const std::function<GmresResult(int budget)>& iterate) {
  const int budget = factorizationCost_ - staleIterations_;
  if (budget <= 0 || lastKrylovIterations_ > budget) return false;
  const GmresResult r = iterate(budget);
  report.krylovIterations += r.iterations;
  staleIterations_ += r.iterations;
  lastKrylovIterations_ = r.iterations;
  return r.converged;
}

void QuasiStaticFracture::solveWithFactorization(const std::vector<double>& rhs, LoadStepReport& report) {
  const bool reuseStale = reuse_ == FactorizationReuse::StaleAsPreconditioner;
  if (hasFactorization_ && !factorizationLive_ && (matrixFactored_ || reuseStale)) rebuildFactorization(report);
  Stopwatch clock;
  bool solved = false;
  if (matrixFactored_) {
    solver_->solve(rhs, x_);
    solved = true;
  } else if (hasFactorization_ && reuseStale) {
    // An older factorization of a nearby matrix (bonds broken since): precondition GMRES with it while
    // that is cheaper than a new factorization.
    solved = iterateWithinBudget(report, [&](int budget) {
      return gmres(system_.A, *solver_, rhs, x_, kKrylovTolerance, budget, kKrylovRestart);
    });
  }
  report.solveSeconds += clock.lap();
  if (!solved) {
    factorizeCurrent(report);
    clock.lap();
    solver_->solve(rhs, x_);
    report.solveSeconds += clock.lap();
  }
}

std::vector<std::uint8_t> QuasiStaticFracture::intactAt(std::size_t broken) const {
  std::vector<std::uint8_t> intact = bonds_.intact;
  for (std::size_t i = broken; i < brokenByLoading_.size(); ++i) {
    const std::size_t k = brokenByLoading_[i];
    intact[k] = intact[bonds_.reverse[k]] = 1;
  }
  return intact;
}

bool QuasiStaticFracture::nearlyFloating(std::size_t p) const {
  // The smallest eigenvalue of the point's 2 x 2 block of u rows against the largest.
  const std::int64_t r = disc_->dofs.u[p];
  if (r < 0) return false;
  const CsrMatrix& A = system_.A;
  const auto entry = [&](std::int64_t row, std::int64_t col) {
    const auto b = A.col.begin() + A.rowStart[row], e = A.col.begin() + A.rowStart[row + 1];
    const auto k = std::lower_bound(b, e, col);
    return k != e && *k == col ? A.value[static_cast<std::size_t>(k - A.col.begin())] : 0.0;
  };
  const double a11 = entry(r, r), a12 = entry(r, r + 1), a21 = entry(r + 1, r), a22 = entry(r + 1, r + 1);
  const double half = 0.5 * (a11 + a22), disc = std::sqrt(std::max(0.0, half * half - (a11 * a22 - a12 * a21)));
  return half - disc < kNearlyFloatingRatio * (half + disc);
}

std::vector<double> QuasiStaticFracture::zonePriority() const {
  // First the points of the bonds the last sub-iteration broke: where the zone missed, damage goes on (the
  // crack tip, a second crack, a corner). Then the points closest to breaking under the last solution, ranked
  // by stretch / s0 (< 1). Against all bonds broken since the last zone (a running crack's path behind its
  // tip, where little breaks again) this cut the zones from 73 to 66 at h = 4 um, f = 0.8
  // (docs/decisions/0011-zone-placement.md).
  std::vector<double> priority = stretchRatios(bonds_, disc_->cloud, disc_->neighbours, u_);
  const Neighbours& nb = disc_->neighbours;
  const std::size_t first = std::max(factoredBroken_, latestBreaks_), end = brokenByLoading_.size();
  for (std::size_t i = first; i < end; ++i) {
    const std::size_t k = brokenByLoading_[i];
    const double latest = 2.0 + static_cast<double>(i - first) / static_cast<double>(end - first);
    for (std::size_t p : {nb.owner(k), static_cast<std::size_t>(nb.index[k])}) priority[p] = std::max(priority[p], latest);
  }
  return priority;
}

std::vector<std::size_t> QuasiStaticFracture::hangingPoints() const {
  // Across them only their spring holds them, kSpringRatio of the bond stiffness, which single-precision sparse
  // factors cannot resolve: their refinement then diverges and the zone falls back to double factors
  // (docs/decisions/0011-zone-placement.md). In the zone they are solved by the dense LU in double.
  // The zone takes their neighbours with them, so that the Schur complement's block of such a point is its own
  // entries, without a single-precision product A_pF A_FF^-1 A_Fp to swamp the small eigenvalue (h = 8 um,
  // f = 0.4, seed 87: the points alone left one fall-back to double factors, with their neighbours none).
  // Outside the core, each costs the zone one horizon, not a core point's two (putting them first in the core
  // made 91 zones there, this 83).
  std::vector<std::size_t> points;
  for (std::size_t p = 0; p < stabilized_.size(); ++p)
    if (stabilized_[p] && nearlyFloating(p)) points.push_back(p);
  return points;
}

void QuasiStaticFracture::factorizeZone(LoadStepReport& report) {
  // The size of the dense Schur complement bounds the zone.
  Stopwatch clock;
  const std::size_t budget = std::min(kZoneUnknowns, static_cast<std::size_t>(disc_->dofs.size) / kZoneShare);
  zone_->factorize(system_.A, zone_->planCore(zonePriority(), kZoneRatio, budget), hangingPoints());
  factoredBroken_ = denseBase_ = brokenByLoading_.size();
  hasFactorization_ = factorizationLive_ = matrixFactored_ = true;
  outsideZone_ = false;
  staleIterations_ = lastKrylovIterations_ = 0;
  dirty_.clear();
  ++report.factorizations;
  report.factorizationSeconds += clock.seconds();
}

void QuasiStaticFracture::rebuildZone(LoadStepReport& report) {
  // After a restore: the sparse factorization of the recorded matrix and zone, then the dense solver's
  // LU and correction rows as the run had them; every row is then checked against the zone as usual.
  Stopwatch clock;
  std::vector<std::uint8_t> stabilized;
  const CsrMatrix factored = assembleFor(intactAt(factoredBroken_), stabilized).A;
  zone_->factorize(factored, restoredCore_, restoredExtra_);
  const CsrMatrix base = denseBase_ == factoredBroken_ ? factored : assembleFor(intactAt(denseBase_), stabilized).A;
  zone_->restoreDense(base, restoredCorrectionOrder_, restoredCorrectionBlocks_, system_.A);
  factorizationLive_ = true;
  dirty_.resize(disc_->cloud.size());
  for (std::size_t p = 0; p < dirty_.size(); ++p) dirty_[p] = p;
  ++report.factorizations;
  report.factorizationSeconds += clock.seconds();
}

void QuasiStaticFracture::solveInZone(const std::vector<double>& rhs, LoadStepReport& report, bool settle) {
  if (hasFactorization_ && !factorizationLive_) rebuildZone(report);
  if (!hasFactorization_) factorizeZone(report);
  Stopwatch clock;
  const int dense = zone_->denseFactorizations();
  const std::int64_t substitutions = zone_->substitutions();
  outsideZone_ = zone_->update(system_.A, dirty_) > 0 || outsideZone_;
  dirty_.clear();
  bool solved = !outsideZone_;
  if (outsideZone_) {
    // Rows changed beyond the zone (the crack left its core, or bonds broke elsewhere): GMRES with the
    // zone solver while that is cheaper than a new zone, searching the directions of the zone's earlier
    // GMRES solves first (h = 2 um, f = 0.2: 42 instead of 44 zones, 1806 instead of 1885 GMRES iterations).
    solved = iterateWithinBudget(report, [&](int budget) {
      return zone_->solveIterative(system_.A, rhs, x_, kKrylovTolerance, budget, kKrylovRestart, true);
    });
  }
  report.solveSeconds += clock.lap();
  if (!solved) factorizeZone(report);
  clock.lap();
  if (!outsideZone_) solveZoneExactly(rhs, report, settle);
  if (zone_->denseFactorizations() != dense) denseBase_ = brokenByLoading_.size();
  report.denseFactorizations += zone_->denseFactorizations() - dense;
  report.substitutions += zone_->substitutions() - substitutions;
  report.solveSeconds += clock.lap();
}

void QuasiStaticFracture::solveZoneExactly(const std::vector<double>& rhs, LoadStepReport& report, bool settle) {
  // Single-precision factors refined in double diverge once the matrix is too ill-conditioned (a fragment
  // held only by the springs; h = 8 um, f = 0.4, seed 87 at U_D = 0.828 um). GMRES preconditioned by the
  // same factors is tried first (refinement by GMRES: it converges where plain refinement does not, and
  // keeps single-precision factors, whose double counterparts set the run's peak memory at h = 2 um);
  // failing that, the zone is factorized in double precision from then on. A double-precision solve that
  // stops short of tol stands as before.
  if (zone_->precision() != FactorPrecision::Single) {
    zone_->solve(system_.A, rhs, x_, kKrylovTolerance);
    return;
  }
  const std::vector<double> start = x_;  // where a fall-back starts again
  if (zone_->solve(system_.A, rhs, x_, kKrylovTolerance, settle ? kSettleTolerance : 0.0, &settledChange_)) return;
  settledChange_ = 0;
  x_ = start;
  const GmresResult rescue =
      zone_->solveIterative(system_.A, rhs, x_, kKrylovTolerance, kRescueIterations, kKrylovRestart);
  report.krylovIterations += rescue.iterations;
  if (rescue.converged) {
    ++report.krylovRescues;
    return;
  }
  zone_->setPrecision(FactorPrecision::Double);
  ++report.precisionFallbacks;
  factorizeZone(report);
  x_ = start;
  zone_->solve(system_.A, rhs, x_, kKrylovTolerance);
}

LoadStepReport QuasiStaticFracture::advance(double load) {
  require(std::isfinite(load), "load must be finite");
  // The last sub-iteration broke nothing, so the matrix is the one x_ solved, and the right-hand side is
  // linear in the load but for the springs' anchors (kSpringRatio of a bond): the scaled solution leaves only
  // their residual, which one substitution removes (h = 8 um, f = 0.2: 998 substitutions instead of 1074).
  if (load_ != 0.0)
    for (double& v : x_) v *= load / load_;
  // Checkpoints fall between load steps and a restored run has no GMRES directions: drop them here too, so that
  // both go on bit for bit.
  if (zone_) zone_->forgetDirections();
  load_ = load;
  LoadStepReport report;
  for (;;) {
    solveCurrent(report);
    ++report.subIterations;
    Stopwatch clock;
    OverstretchVerdict verdict =
        findOverstretched(bonds_, disc_->cloud, disc_->neighbours, u_, kErrorPerChange * settledChange_);
    report.bondCheckSeconds += clock.lap();
    // A settled solution decides the breaks only when no bond is near its s0; the last sub-iteration of a load
    // step ends refined to tolerance (the reported forces, the next load step's start and checkpoints).
    if (settledChange_ > 0 && (!verdict.certain || verdict.bonds.empty())) {
      finishSolve(report);
      clock.lap();
      if (!verdict.certain) verdict = findOverstretched(bonds_, disc_->cloud, disc_->neighbours, u_, 0.0);
      report.bondCheckSeconds += clock.lap();
    }
    const std::vector<std::size_t>& fresh = verdict.bonds;
    breakBonds(bonds_, fresh);
    if (fresh.empty()) break;
    latestBreaks_ = brokenByLoading_.size();
    brokenByLoading_.insert(brokenByLoading_.end(), fresh.begin(), fresh.end());
    report.newlyBroken += fresh.size();
    // The reference assembles afresh, so that it checks the row updates of the other drivers.
    if (reuse_ == FactorizationReuse::RefactorizeEveryChange)
      assemble(&report);
    else
      reassembleAround(fresh, report);
    if (subIterationHook_) subIterationHook_(report);
    if (report.subIterations >= kMaxSubIterations)
      throw SolverFailure("no equilibrium after " + std::to_string(kMaxSubIterations) + " sub-iterations");
  }
  return report;
}

std::array<double, 2> QuasiStaticFracture::collarForce(const std::vector<std::uint8_t>& collar) const {
  return peristep::collarForce(*disc_, material_.lambda, material_.mu, u_, x_, collar, &bonds_.intact);
}

std::vector<std::uint8_t> QuasiStaticFracture::saveState() const {
  ByteWriter w;
  w.put(load_);
  w.putArray(u_);
  w.putArray(x_);
  w.putArray(bonds_.intact);
  w.putArray(brokenByLoading_);
  w.put<std::uint64_t>(latestBreaks_);
  w.put<std::uint8_t>(hasFactorization_);
  w.put<std::uint64_t>(factoredBroken_);
  w.put<std::int32_t>(staleIterations_);
  w.put<std::int32_t>(lastKrylovIterations_);
  w.put<std::uint64_t>(denseBase_);
  w.putArray(zone_ && hasFactorization_ ? zone_->corePoints() : std::vector<std::size_t>{});
  w.putArray(zone_ && hasFactorization_ ? zone_->extraPoints() : std::vector<std::size_t>{});
  w.putArray(zone_ && hasFactorization_ ? zone_->correctionOrder() : std::vector<std::size_t>{});
  w.putArray(zone_ && hasFactorization_ ? zone_->correctionBlocks() : std::vector<std::size_t>{});
  w.put<std::uint8_t>(zone_ && zone_->precision() == FactorPrecision::Single);
  return w.take();
}

void QuasiStaticFracture::restoreState(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes);
  const double load = r.get<double>();
  auto u = r.getArray<double>(u_.size());
  auto x = r.getArray<double>(x_.size());
  auto intact = r.getArray<std::uint8_t>(bonds_.intact.size());
  auto broken = r.getArray<std::size_t>();
  const auto latestBreaks = r.get<std::uint64_t>();
  const bool hasFactorization = r.get<std::uint8_t>() != 0;
  const auto factoredBroken = r.get<std::uint64_t>();
  const auto stale = r.get<std::int32_t>();
  const auto lastKrylov = r.get<std::int32_t>();
  const auto denseBase = r.get<std::uint64_t>();
  auto core = r.getArray<std::size_t>();
  auto extra = r.getArray<std::size_t>();
  auto correctionOrder = r.getArray<std::size_t>();
  auto correctionBlocks = r.getArray<std::size_t>();
  const bool singleFactors = r.get<std::uint8_t>() != 0;
  r.expectEnd();
  // The state may have been taken after a fall-back to double factors (or before one that came later).
  if (zone_) zone_->setPrecision(singleFactors ? FactorPrecision::Single : FactorPrecision::Double);
  if (factoredBroken > broken.size() || denseBase > broken.size() || latestBreaks > broken.size())
    throw InvalidInput("serialized FMU state is corrupt: factorization index");
  for (const auto* points : {&core, &extra})
    for (std::size_t p : *points)
      if (p >= disc_->cloud.size()) throw InvalidInput("serialized FMU state is corrupt: crack zone");
  for (std::size_t k : broken)
    if (k >= intact.size()) throw InvalidInput("serialized FMU state is corrupt: broken-bond index");
  load_ = load;
  u_ = std::move(u);
  x_ = std::move(x);
  bonds_.intact = std::move(intact);
  brokenByLoading_ = std::move(broken);
  latestBreaks_ = static_cast<std::size_t>(latestBreaks);
  hasFactorization_ = hasFactorization;
  factoredBroken_ = static_cast<std::size_t>(factoredBroken);
  staleIterations_ = stale;
  lastKrylovIterations_ = lastKrylov;
  denseBase_ = static_cast<std::size_t>(denseBase);
  restoredCore_ = std::move(core);
  restoredExtra_ = std::move(extra);
  restoredCorrectionOrder_ = std::move(correctionOrder);
  restoredCorrectionBlocks_ = std::move(correctionBlocks);
  dirty_.clear();
  outsideZone_ = false;  // rebuildZone finds it again
  factorizationLive_ = false;
  assemble(nullptr);
  matrixFactored_ = hasFactorization_ && factoredBroken_ == brokenByLoading_.size();
}

}  // namespace peristep
