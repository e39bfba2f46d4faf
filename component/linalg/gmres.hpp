#pragma once
// Restarted GMRES, right-preconditioned: used to reuse a factorization of a nearby matrix (a few bonds broken
// since it was computed) instead of refactorizing. It can keep the directions it found for the next solves with
// the same preconditioner (GCRO with a recycled space: de Sturler 1999; Parks et al. 2006 recycle across the
// systems of a growing crack): while a crack-zone factorization serves a matrix that changed outside the zone,
// each solve otherwise searches again for all the changes since the factorization; with the directions kept,
// a solve searches only what is new (docs/decisions/0002-recycled-gmres.md).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "core/csr_matrix.hpp"
#include "linalg/linear_solver.hpp"

namespace peristep {

struct GmresResult {
  bool converged = false;
  int iterations = 0;
  double relativeResidual = 0;
};

using VectorMap = std::function<void(std::span<const double>, std::span<double>)>;

// Pairs (z_k, c_k = A z_k) in row-major n x capacity storage, and their Gram matrix C^T C. A may change in some
// rows between solves: refreshRow() recomputes c_k in that row, so C = A Z holds for the current A.
class RecycledDirections {
 public:
  explicit RecycledDirections(std::size_t capacity) : capacity_(capacity) {}

  std::size_t size() const { return count_; }
  // Forgets every direction and frees their memory (a new preconditioner: the sparse factorization that
  // follows sets the run's peak memory).
  void clear();
  // Forgets every direction and keeps the memory for the next ones.
  void forget();
  // Row i of the operator D A D changed: with its entries of A (columns, values) and the scaling D.
  void refreshRow(std::size_t i, std::span<const std::int64_t> columns, std::span<const double> values,
                  std::span<const double> scale);

 private:
  friend GmresResult gmres(const VectorMap&, const VectorMap&, std::span<const double>, std::span<double>, double,
                           int, int, RecycledDirections*);
  std::size_t capacity_, n_ = 0, count_ = 0, pending_ = 0;
  std::vector<double> z_, c_;  // row-major: entry (i, k) at i * capacity_ + k
  std::vector<double> gram_;   // capacity_ x capacity_, C^T C of the first count_ columns
  void reserve(std::size_t n);
  void stage(std::span<const double> z, std::span<const double> c);  // a new pair, joins at commit()
  void commit();
};

// Solves A x = b starting from x; stops at ||b - A x|| <= tol ||b|| or after maxIterations. With `kept`, it first
// takes the best combination of the kept directions (least squares on C), keeps every Krylov vector orthogonal
// to range(C), and hands its own directions to `kept` when it returns; without, it is plain GMRES.
GmresResult gmres(const VectorMap& apply, const VectorMap& precondition, std::span<const double> b,
                  std::span<double> x, double tol, int maxIterations, int restart = 30,
                  RecycledDirections* kept = nullptr);

// The same with a matrix and a solver as the preconditioner.
GmresResult gmres(const CsrMatrix& A, LinearSolver& preconditioner, std::span<const double> b, std::span<double> x,
                  double tol, int maxIterations, int restart = 30);

}  // namespace peristep
