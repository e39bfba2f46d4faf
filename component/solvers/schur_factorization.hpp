#pragma once
// Sparse LU of A with a chosen set of unknowns Z eliminated last (MUMPS, sequential): the factors of the
// rest, A_FF, and the dense Schur complement S = A_ZZ - A_ZF A_FF^-1 A_FZ. When only the Z x Z block of A
// changes, A_new x = b is solved with the same factors and S + (A_new - A)_ZZ: the fracture driver puts the
// crack zone in Z, so that the bonds breaking there never require a new sparse factorization.
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "core/csr_matrix.hpp"

namespace peristep {

class SchurFactorization {
 public:
  SchurFactorization();
  ~SchurFactorization();
  SchurFactorization(const SchurFactorization&) = delete;
  SchurFactorization& operator=(const SchurFactorization&) = delete;

  // Factorizes A (square, its pattern fixed for the lifetime of this object) with `schurUnknowns`
  // (ascending, possibly empty) eliminated last, in the order `position` (the pivot position of each
  // unknown, the Schur unknowns last). A is read during this call only. The analysis is repeated only
  // when the set or the order changes.
  void factorize(const CsrMatrix& A, const std::vector<std::int64_t>& schurUnknowns,
                 const std::vector<std::int32_t>& position);

  // S, column-major, size |Z| x |Z|.
  const std::vector<double>& schurComplement() const { return schur_; }
  std::vector<double> takeSchurComplement() { return std::move(schur_); }

  // First half of a solve: the reduced right-hand side b_Z - A_ZF A_FF^-1 b_F (size |Z|). The solver keeps
  // the forward-eliminated b for expand().
  void condense(std::span<const double> b, std::span<double> reduced);
  // Second half: given x_Z, the full solution x (x_Z in its place).
  void expand(std::span<const double> xZ, std::span<double> x);
  // Plain solve when Z is empty.
  void solve(std::span<const double> b, std::span<double> x);

 private:
  struct Mumps;
  // Memory mapped once and kept: MUMPS's main work array across factorizations.
  struct Workspace {
    void* data = nullptr;
    std::size_t bytes = 0;
    Workspace() = default;
    Workspace& operator=(Workspace&& o) noexcept {
      std::swap(data, o.data);
      std::swap(bytes, o.bytes);
      return *this;
    }
    ~Workspace();
  };
  void call(int job, const char* what);
  void useWorkspace();

  std::unique_ptr<Mumps> mumps_;
  std::vector<int> rowIndex_, colIndex_;  // 1-based coordinates of A's entries
  std::vector<std::int64_t> schurUnknowns_;
  std::vector<int> schurList_, position_;  // 1-based, for MUMPS
  std::vector<double> schur_, rhs_;
  bool analyzed_ = false;
  std::int64_t workspaceEstimate_ = 0;  // MUMPS' estimate of S after the analysis, entries
  Workspace workspace_;  // outlives the MUMPS instance: the destructor terminates MUMPS first
};

}  // namespace peristep
