#pragma once
// Dense solves with a matrix whose rows change a few at a time: M = S + (changes of some rows), with an LU
// of an earlier M (M0) reused through the Woodbury identity,
//   (M0 + E_R D)^-1 = M0^-1 - W (I + D W)^-1 D M0^-1,   W = M0^-1 E_R,
// R the rows changed since M0 and D their changes. A column of W costs one pair of triangular solves and
// is computed once per row (it depends on the row only through E_R); when R grows past a fraction of the
// size, M is factorized afresh. Used on the crack zone's Schur complement (linalg/schur_factorization.hpp).
#include <cstdint>
#include <span>
#include <vector>

namespace peristep {

class DenseRowUpdateSolver {
 public:
  // S: column-major n x n; all row changes are relative to it.
  void reset(std::vector<double> S);
  // Frees the matrix, its LU and the correction until the next reset() (the counts stay).
  void release();
  std::size_t size() const { return n_; }

  // Row i of M is now S[i, columns] + change (columns ascending, fixed per row).
  void setRow(std::size_t i, const std::vector<std::int32_t>& columns, const std::vector<double>& change);

  // A fresh LU of M as it is now (the rows' changes become part of M0).
  void refactorize();
  // Rows in the Woodbury correction, in the order they entered it, and the ends of the blocks in which
  // their W columns were computed: a checkpoint sets the rows in this order, then replays the blocks.
  const std::vector<std::size_t>& correctedRowOrder() const { return updated_; }
  const std::vector<std::size_t>& correctionBlocks() const { return blockEnds_; }
  void replayCorrection(std::span<const std::size_t> blockEnds);

  // x = M^-1 r.
  void solve(std::span<const double> r, std::span<double> x);

  // Fresh LU factorizations of M so far (the first one included), rows in the Woodbury correction now.
  int factorizations() const { return factorizations_; }
  std::size_t correctedRows() const { return updated_.size(); }

 private:
  struct Row {
    std::vector<std::int32_t> columns;
    std::vector<double> change, factored;  // current change; the change M0 was factorized with
    std::int64_t slot = -1;                // column of W, -1 while the row equals M0's
  };
  void extendCorrection(std::size_t k);
  void factorizeCapacitance(std::size_t k);
  void luSolve(const std::vector<double>& lu, const std::vector<int>& pivots, std::size_t n, double* b, int nrhs) const;

  std::size_t n_ = 0;
  std::vector<double> S_, lu_;
  std::vector<int> pivots_;
  std::vector<Row> rows_;
  std::vector<std::size_t> updated_;  // rows with a W column, in order of their slots
  std::vector<std::size_t> blockEnds_;
  std::vector<double> W_;             // n x updated_.size(), column-major
  // LU of the capacitance matrix I + D W for the first capacitanceRows_ corrected rows: it depends on the
  // rows' changes only, so every solve until the next setRow() that changes a corrected row reuses it.
  std::vector<double> capacitance_;
  std::vector<int> capacitancePivots_;
  std::size_t capacitanceRows_ = 0;
  int factorizations_ = 0;
};

}  // namespace peristep
