#include "linalg/dense_row_update_solver.hpp"

#include <lapack.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/memory.hpp"


namespace peristep {
namespace {

void luFactorize(std::vector<double>& a, std::vector<int>& pivots, std::size_t n) {
  const int m = static_cast<int>(n);
  pivots.resize(n);
  int info = 0;
  LAPACK_dgetrf(&m, &m, a.data(), &m, pivots.data(), &info);
  if (info != 0) throw SolverFailure("dense LU of the crack zone failed (info " + std::to_string(info) + ")");
}

}  // namespace

void DenseRowUpdateSolver::reset(std::vector<double> S) {
  n_ = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(S.size()))));
  require(n_ * n_ == S.size(), "dense solver: the matrix must be square");
  S_ = std::move(S);
  rows_.assign(n_, Row{});
  factorizations_ = 0;
  refactorize();
}

void DenseRowUpdateSolver::release() {
  n_ = 0;
  freeStorage(S_);
  freeStorage(lu_);
  freeStorage(W_);
  freeStorage(pivots_);
  freeStorage(rows_);
  freeStorage(updated_);
  freeStorage(blockEnds_);
  freeStorage(capacitance_);
  freeStorage(capacitancePivots_);
  capacitanceRows_ = 0;
}

void DenseRowUpdateSolver::setRow(std::size_t i, const std::vector<std::int32_t>& columns,
                                  const std::vector<double>& change) {
  Row& row = rows_[i];
  if (row.columns.empty()) {
    row.columns = columns;
    row.factored.assign(columns.size(), 0.0);
  }
  if (row.slot >= 0 && change != row.change) capacitanceRows_ = 0;  // D changed: I + D W must be formed again
  row.change = change;
  if (row.slot < 0 && row.change != row.factored) {
    row.slot = static_cast<std::int64_t>(updated_.size());
    updated_.push_back(i);
  }
}

void DenseRowUpdateSolver::refactorize() {
  lu_ = S_;
  for (std::size_t i = 0; i < n_; ++i) {
    Row& row = rows_[i];
    for (std::size_t k = 0; k < row.columns.size(); ++k)
      lu_[static_cast<std::size_t>(row.columns[k]) * n_ + i] += row.change[k];
    row.factored = row.change;
    row.slot = -1;
  }
  updated_.clear();
  blockEnds_.clear();
  W_.clear();
  capacitanceRows_ = 0;
  if (n_ > 0) luFactorize(lu_, pivots_, n_);
  ++factorizations_;
}

void DenseRowUpdateSolver::luSolve(const std::vector<double>& lu, const std::vector<int>& pivots, std::size_t n,
                                   double* b, int nrhs) const {
  const int m = static_cast<int>(n);
  int info = 0;
  LAPACK_dgetrs("N", &m, &nrhs, lu.data(), &m, pivots.data(), b, &m, &info);
  if (info != 0) throw SolverFailure("dense triangular solve failed");
}

void DenseRowUpdateSolver::extendCorrection(std::size_t k) {
  // New columns of W = M0^-1 E_R, solved as one block (one pass over the LU). A block rounds differently
  // from other blocks, so the block ends are recorded: a restored checkpoint replays them.
  const std::size_t have = W_.size() / n_;
  if (have >= k) return;
  W_.resize(n_ * k, 0.0);
  for (std::size_t s = have; s < k; ++s) W_[s * n_ + updated_[s]] = 1.0;
  luSolve(lu_, pivots_, n_, W_.data() + have * n_, static_cast<int>(k - have));
  blockEnds_.push_back(k);
}

void DenseRowUpdateSolver::replayCorrection(std::span<const std::size_t> blockEnds) {
  for (std::size_t k : blockEnds) {
    require(k <= updated_.size(), "dense solver: the correction to replay is longer than its rows");
    extendCorrection(k);
  }
}

void DenseRowUpdateSolver::factorizeCapacitance(std::size_t k) {
  // C = I + D W: it depends on the rows' changes and W only, so the solves of one set of changes (refinement
  // steps, GMRES iterations) share its LU (h = 4 um: ~2 ms of a 9 ms dense solve when formed in every solve).
  capacitance_.assign(k * k, 0.0);
  for (std::size_t a = 0; a < k; ++a) {
    const Row& row = rows_[updated_[a]];
    capacitance_[a * k + a] = 1.0;
    for (std::size_t e = 0; e < row.columns.size(); ++e) {
      const double d = row.change[e] - row.factored[e];
      if (d == 0.0) continue;
      const auto c = static_cast<std::size_t>(row.columns[e]);
      for (std::size_t b = 0; b < k; ++b) capacitance_[b * k + a] += d * W_[b * n_ + c];
    }
  }
  luFactorize(capacitance_, capacitancePivots_, k);
  capacitanceRows_ = k;
}

void DenseRowUpdateSolver::solve(std::span<const double> r, std::span<double> x) {
  // A W column costs 2 n^2 flops, a fresh LU 2/3 n^3: beyond n/6 corrected rows (plus the k^3 of the
  // capacitance matrix below) a new LU is cheaper over the next solves.
  if (updated_.size() > std::max<std::size_t>(64, n_ / 6)) refactorize();
  std::copy(r.begin(), r.end(), x.begin());
  if (n_ == 0) return;
  luSolve(lu_, pivots_, n_, x.data(), 1);
  const std::size_t k = updated_.size();
  if (k == 0) return;
  extendCorrection(k);
  if (capacitanceRows_ != k) factorizeCapacitance(k);
  // t = C^-1 D y: D the rows' changes since M0, y = M0^-1 r.
  std::vector<double> t(k, 0.0);
  for (std::size_t a = 0; a < k; ++a) {
    const Row& row = rows_[updated_[a]];
    for (std::size_t e = 0; e < row.columns.size(); ++e) {
      const double d = row.change[e] - row.factored[e];
      if (d != 0.0) t[a] += d * x[static_cast<std::size_t>(row.columns[e])];
    }
  }
  luSolve(capacitance_, capacitancePivots_, k, t.data(), 1);
  for (std::size_t b = 0; b < k; ++b)
    for (std::size_t i = 0; i < n_; ++i) x[i] -= W_[b * n_ + i] * t[b];
}

}  // namespace peristep
