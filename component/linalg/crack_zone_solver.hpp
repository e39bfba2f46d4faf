#pragma once
// Solves the fracture system A x = b while bonds break, with one sparse factorization per crack zone.
// The zone is a set of core points whose rows may change (bonds may break there) and the points within
// delta of them (the columns of those rows). Its unknowns Z are eliminated last: the sparse factors of the
// rest and the dense Schur complement S come from one sparse factorization (SchurFactorization); a change of a zone row within the
// zone's columns (any change of a core row; of the other zone rows, e.g. the free-surface term of a point
// near a break, 000:(3.19)) changes only the Z x Z block, so the solve uses S + (A - A_factored)_ZZ
// (DenseRowUpdateSolver) and the same sparse factors. A change beyond that needs a new zone and factorization.
#include <cstdint>
#include <span>
#include <vector>

#include "core/csr_matrix.hpp"
#include "geometry/dof_map.hpp"
#include "geometry/neighbours.hpp"
#include "linalg/dense_row_update_solver.hpp"
#include "linalg/gmres.hpp"
#include "linalg/patch_correction.hpp"
#include "linalg/schur_factorization.hpp"

namespace peristep {

class CrackZoneSolver {
 public:
  // solveIterative() keeps up to `keptDirections` GMRES directions between solves.
  CrackZoneSolver(const Neighbours& nb, const DofMap& dofs, FactorPrecision precision, std::size_t keptDirections = 0)
      : nb_(nb), dofs_(dofs), sparse_(precision), kept_(keptDirections), patch_(nb, dofs) {}

  // Factorizes A with the zone of `corePoints` (ascending) eliminated last. `extraPoints` (ascending) and their
  // neighbours join the zone but not the core: points the sparse factors should not see, whose own rows' changes
  // still go to GMRES.
  void factorize(const CsrMatrix& A, std::vector<std::size_t> corePoints, std::vector<std::size_t> extraPoints = {});
  // A core for the next factorization: the points with priority >= threshold, highest first, each with
  // its neighbours (the rows a break of its bonds changes), while the zone has at most `budget` unknowns.
  std::vector<std::size_t> planCore(const std::vector<double>& priority, double threshold, std::size_t budget) const;

  // The rows of `points` (ascending) in A may differ from the factorized matrix: hand the changes of the
  // zone's rows within its columns to the dense zone solver; returns how many changed rows reach beyond them
  // (rows outside the zone, or zone rows changed in other columns: solveIterative() handles those).
  std::size_t update(const CsrMatrix& A, std::span<const std::size_t> points);

  // x = A^-1 b for the current A (the factorized one plus the updates), refined from the given x against A
  // until the componentwise backward error max_i |b - A x|_i / (|A| |x| + |b|)_i is at most tol; false
  // when it does not get there (x is then not to be used): single-precision factors of a matrix whose
  // condition number passes ~1e7 (a fragment held only by the driver's springs) do not converge.
  // With settleTol > tol it also stops, returning true, once the backward error is at most settleTol, and sets
  // *lastChange to the largest change of a displacement unknown in the last correction (0 when it reached tol):
  // the error left is a small fraction of it (single-precision factors contract the error ~1e-6 per correction).
  bool solve(const CsrMatrix& A, std::span<const double> b, std::span<double> x, double tol, double settleTol = 0,
             double* lastChange = nullptr);

  FactorPrecision precision() const { return sparse_.precision(); }
  // From the next factorize() on.
  void setPrecision(FactorPrecision precision) { sparse_.setPrecision(precision); }

  // Checkpoints: the dense solver's state is a function of the matrix its LU was last computed with (base)
  // and of the order in which rows entered its correction since; restoring replays both.
  const std::vector<std::size_t>& correctionOrder() const { return dense_.correctedRowOrder(); }
  const std::vector<std::size_t>& correctionBlocks() const { return dense_.correctionBlocks(); }
  void restoreDense(const CsrMatrix& base, std::span<const std::size_t> correctionOrder,
                    std::span<const std::size_t> correctionBlocks, const CsrMatrix& A);

  // A x = b when rows outside the core changed too: GMRES on the scaled system D A D, preconditioned by
  // the zone solver (exact up to those rows) with a local correction around those rows
  // (linalg/patch_correction.hpp), from x; stops at relative residual tol. x is left as it was
  // when the iteration became non-finite. With `recycle`, the directions of earlier such solves since the last
  // factorize() or forgetDirections() are searched first and this solve's join them.
  GmresResult solveIterative(const CsrMatrix& A, std::span<const double> b, std::span<double> x, double tol,
                             int maxIterations, int restart, bool recycle = false);
  // Drops the kept directions (a restored checkpoint starts without them, so a run drops them where one can start).
  void forgetDirections() { kept_.forget(); }

  const std::vector<std::size_t>& corePoints() const { return core_; }
  const std::vector<std::size_t>& extraPoints() const { return extra_; }
  int denseFactorizations() const { return dense_.factorizations(); }
  // Solves with the factors so far (condensation, dense zone solve, expansion), in refinement and GMRES.
  std::int64_t substitutions() const { return substitutions_; }
  std::int64_t factorEntries() const { return sparse_.factorEntries(); }

 private:
  void solveOnce(std::span<const double> b, std::span<double> x);
  void solveScaled(std::span<const double> b, std::span<double> y);
  std::vector<std::int64_t> zoneUnknowns() const;
  // All points with unknowns in nested-dissection order of their neighbour graph (the pattern of every A).
  std::vector<std::size_t> dissectionOrder() const;
  std::vector<std::int32_t> pivotOrder() const;
  enum class RowChange { None, InZone, BeyondZone };
  // The change (A - factored) of row `row` on the zone's columns, and where the row changed at all.
  RowChange rowChange(const CsrMatrix& A, std::int64_t row, std::vector<std::int32_t>& columns,
                      std::vector<double>& change) const;
  // Hands a zone row's change on the zone's columns to the dense solver; counts in `beyond` a change it
  // cannot take up.
  void setZoneRow(const CsrMatrix& A, std::int64_t row, std::vector<std::int32_t>& columns,
                  std::vector<double>& change, std::size_t& beyond);

  const Neighbours& nb_;
  const DofMap& dofs_;
  // The factorized matrix's entries (its pattern is every later matrix's): the changes are measured from them.
  std::vector<double> factored_;
  // Symmetric diagonal scaling D = |diag A|^-1/2 of the factorized matrix: the u rows are ~1e20 times the
  // theta rows, and the sparse LU factorizes D A D (neither it nor MUMPS scales when a Schur complement is asked for).
  std::vector<double> scale_;
  SchurFactorization sparse_;
  DenseRowUpdateSolver dense_;
  std::vector<std::size_t> core_, extra_;
  std::vector<std::size_t> dissection_;  // dissectionOrder(), from the first factorize() on
  std::vector<std::int64_t> zone_;       // zone unknowns, ascending
  std::vector<std::int32_t> zoneIndex_;  // per unknown: position in zone_, -1 outside
  std::vector<std::uint8_t> takesUp_;    // per zone row: its changes within the zone go to the dense solver
  RecycledDirections kept_;
  // Rows counted as changed beyond the zone since factorize(), in the order found (and a flag per unknown):
  // solveIterative() builds its patch correction around them.
  std::vector<std::int64_t> beyondRows_;
  std::vector<std::uint8_t> isBeyondRow_;
  PatchCorrection patch_;
  std::vector<double> reduced_, xZone_;
  std::int64_t substitutions_ = 0;
};

}  // namespace peristep
