#pragma once
// Quasi-static brittle fracture with the heterogeneous LPS model (000 Sec. 3.3, Sec. 5): at each load
// solve, break every bond over its critical stretch, re-solve at the same load until no new bond breaks.
#include <array>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fracture/bond_state.hpp"
#include "linalg/crack_zone_solver.hpp"
#include "linalg/gmres.hpp"
#include "linalg/linear_solver.hpp"
#include "models/lps_discretization.hpp"

namespace peristep {

struct FractureMaterial {
  std::vector<double> lambda, mu, fractureEnergy;  // per point
};

struct LoadStepReport {
  int subIterations = 0;       // solves at this load
  int factorizations = 0;      // numeric factorizations among them
  int krylovIterations = 0;    // GMRES iterations preconditioned by an older factorization
  int denseFactorizations = 0; // dense LU factorizations of the crack zone's Schur complement
  std::int64_t substitutions = 0;  // solves with the crack zone's factors (refinement and GMRES included)
  int precisionFallbacks = 0;  // single-precision zone factors that did not converge: double from then on
  int krylovRescues = 0;       // zone solves whose refinement diverged and GMRES with the same factors finished
  std::size_t newlyBroken = 0; // pairs broken at this load
  // Wall time of the phases (profiling only: no decision depends on them, so runs stay reproducible).
  double assemblySeconds = 0, factorizationSeconds = 0, solveSeconds = 0, bondCheckSeconds = 0;

  LoadStepReport& operator+=(const LoadStepReport& o) {
    subIterations += o.subIterations;
    factorizations += o.factorizations;
    krylovIterations += o.krylovIterations;
    denseFactorizations += o.denseFactorizations;
    substitutions += o.substitutions;
    precisionFallbacks += o.precisionFallbacks;
    krylovRescues += o.krylovRescues;
    newlyBroken += o.newlyBroken;
    assemblySeconds += o.assemblySeconds;
    factorizationSeconds += o.factorizationSeconds;
    solveSeconds += o.solveSeconds;
    bondCheckSeconds += o.bondCheckSeconds;
    return *this;
  }
};

// Precision of the CrackZone driver's sparse factors: single, refined in double. Same crack histories as the
// reference at h = 8 and 4 um, 21-28% less memory, 11-26% less CPU time
// (docs/decisions/0001-own-single-precision-lu.md).
inline constexpr FactorPrecision kZoneFactorPrecision = FactorPrecision::Single;

// How the solves after a break use the factorization of an older matrix.
enum class FactorizationReuse {
  // One sparse factorization per crack zone (linalg/crack_zone_solver.hpp): the zone around the bonds
  // closest to breaking is condensed to a dense Schur complement that takes up the rows that breaking
  // changes, so that a new sparse factorization is needed only when the crack leaves the zone (production).
  CrackZone,
  // GMRES preconditioned by the older factorization while that is cheaper than a new one.
  StaleAsPreconditioner,
  // A new factorization at every change of the matrix and a direct solve, no GMRES: the reference whose
  // crack history the production driver must repeat exactly (tests/fracture_driver_test.cpp).
  RefactorizeEveryChange,
};

class QuasiStaticFracture {
 public:
  // unitCollarDisplacement: (u_x, u_y) of every point for load 1; the collar follows load * it
  // (the problem has no body force).
  QuasiStaticFracture(std::shared_ptr<const LpsDiscretization> disc, FractureMaterial material, BondState bonds,
                      std::vector<double> unitCollarDisplacement, LinearSolverKind solver = LinearSolverKind::Umfpack,
                      FactorizationReuse reuse = FactorizationReuse::CrackZone,
                      FactorPrecision zonePrecision = kZoneFactorPrecision);

  LoadStepReport advance(double load);
  // Called after every sub-iteration that broke bonds, with the state consistent (saveState() then
  // advance() at the same load continues the step exactly) and the step's report so far: long runs
  // checkpoint from here.
  void onSubIteration(std::function<void(const LoadStepReport&)> hook) { subIterationHook_ = std::move(hook); }

  const LpsDiscretization& discretization() const { return *disc_; }
  const BondState& bonds() const { return bonds_; }
  // The current system matrix (unknown-unknown block).
  const CsrMatrix& matrix() const { return system_.A; }
  // Entries of the crack zone's last sparse factors (0 for the other drivers).
  std::int64_t zoneFactorEntries() const { return zone_ ? zone_->factorEntries() : 0; }
  // Points the crack zone in use holds, with their neighbours, for hanging by their springs (hangingPoints()).
  std::size_t zoneHangingPoints() const { return zone_ ? zone_->extraPoints().size() : 0; }
  // (u_x, u_y) of every point (the collar included).
  const std::vector<double>& displacement() const { return u_; }
  double load() const { return load_; }
  // Pairs broken by loading so far (CSR positions), in breaking order.
  const std::vector<std::size_t>& brokenByLoading() const { return brokenByLoading_; }
  // Net force the points of `collar` exert on the domain (per unit thickness).
  std::array<double, 2> collarForce(const std::vector<std::uint8_t>& collar) const;

  // Checkpoint of what changes while loading: load, displacement, bond state, broken list, and which
  // matrix the factorization in use belongs to (restoring refactorizes that one, so that the
  // preconditioned solves, and with them the run, repeat bit for bit).
  std::vector<std::uint8_t> saveState() const;
  void restoreState(std::span<const std::uint8_t> bytes);

 private:
  LpsSystem assembleFor(const std::vector<std::uint8_t>& intact, std::vector<std::uint8_t>& stabilized) const;
  void assemble(LoadStepReport* report);
  // Recomputes in place the rows that breaking `fresh` changed (and marks them for the crack zone).
  void reassembleAround(const std::vector<std::size_t>& fresh, LoadStepReport& report);
  void addSprings(LpsSystem& s, std::span<const std::size_t> points, const std::vector<std::uint8_t>& stabilized) const;
  void factorizeZone(LoadStepReport& report);
  // Per point, its claim to the next crack zone (CrackZoneSolver::planCore).
  std::vector<double> zonePriority() const;
  // Whether the point hangs by its spring in one direction (its 2 x 2 block of u rows nearly singular).
  bool nearlyFloating(std::size_t point) const;
  // The points with a broken bond that hang so (ascending): they and their neighbours join the next zone.
  std::vector<std::size_t> hangingPoints() const;
  void rebuildZone(LoadStepReport& report);
  // With `settle`, the zone's refinement may stop early (CrackZoneSolver::solve), leaving settledChange_ > 0.
  void solveInZone(const std::vector<double>& rhs, LoadStepReport& report, bool settle);
  void solveZoneExactly(const std::vector<double>& rhs, LoadStepReport& report, bool settle);
  void solveWithFactorization(const std::vector<double>& rhs, LoadStepReport& report);
  // Ski rental: GMRES with an older factorization while the iterations spent on it stay below the price of
  // a new one (so at most twice the better choice is paid); false when over budget or not converged.
  bool iterateWithinBudget(LoadStepReport& report, const std::function<GmresResult(int budget)>& iterate);
  std::vector<std::uint8_t> intactAt(std::size_t broken) const;
  void factorizeCurrent(LoadStepReport& report);
  void rebuildFactorization(LoadStepReport& report);
  // The zone's refinement may settle (CrackZoneSolver::solve): then settledChange_ > 0.
  void solveCurrent(LoadStepReport& report);
  // Refines a settled solution to tolerance.
  void finishSolve(LoadStepReport& report);
  // u_ from x_ and the prescribed displacements.
  void takeSolution();

  std::shared_ptr<const LpsDiscretization> disc_;
  FractureMaterial material_;
  BondState bonds_;
  std::vector<double> unitCollar_;
  std::unique_ptr<LinearSolver> solver_;
  FactorizationReuse reuse_;
  LpsSystem system_;
  std::vector<std::uint8_t> stabilized_;  // points held by the springs (they have a broken bond)
  // The matrix solver_ factorized (kept alive for it; the crack zone keeps its own values) and the state it
  // belongs to: the bonds intact now plus brokenByLoading_[factoredBroken_..] (bonds only break, in that
  // recorded order).
  CsrMatrix factoredA_;
  std::size_t factoredBroken_ = 0;
  bool hasFactorization_ = false;  // a factorization of the state above exists (in solver_)
  bool factorizationLive_ = false; // ... and solver_ holds it (false after a restore until rebuilt)
  bool matrixFactored_ = false;    // system_.A is the factored matrix (no bond broken since)
  int staleIterations_ = 0;        // GMRES iterations spent on the factorization since it was computed
  int lastKrylovIterations_ = 0;
  int factorizationCost_ = 0;      // one factorization priced in GMRES iterations (see the .cpp)
  std::unique_ptr<CrackZoneSolver> zone_;  // CrackZone only
  std::vector<std::size_t> dirty_;          // points whose rows were recomputed since the last solve
  bool outsideZone_ = false;                // rows changed beyond the zone since it was factorized
  std::size_t denseBase_ = 0;               // brokenByLoading_ size when the zone's dense LU was computed
  // From restoreState, until the zone is rebuilt.
  std::vector<std::size_t> restoredCore_, restoredExtra_, restoredCorrectionOrder_, restoredCorrectionBlocks_;
  std::vector<double> u_, x_;      // u of all points; last unknown vector (warm start)
  std::vector<double> rhs_;        // of the last solve
  double settledChange_ = 0;       // > 0: x_ settled short of tolerance, its last correction's largest change
  std::vector<std::size_t> brokenByLoading_;
  std::size_t latestBreaks_ = 0;   // brokenByLoading_[latestBreaks_..]: the last sub-iteration's breaks
  double load_ = 0;
  std::function<void(const LoadStepReport&)> subIterationHook_;
};

}  // namespace peristep
