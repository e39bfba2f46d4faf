#pragma once
// Sparse LU of A with a chosen set of unknowns Z eliminated last: the factors of the
// rest, A_FF, and the dense Schur complement S = A_ZZ - A_ZF A_FF^-1 A_FZ. When only the Z x Z block of A
// changes, A_new x = b is solved with the same factors and S + (A_new - A)_ZZ: the fracture driver puts the
// crack zone in Z, so that the bonds breaking there never require a new sparse factorization.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/csr_matrix.hpp"

namespace peristep {

// Precision of the sparse factors: double (MUMPS' dmumps, sequential, with threshold pivoting) or single (the
// project's multifrontal LU without pivoting, linalg/multifrontal_lu.hpp). The interface is double either way: A, S and
// the vectors are converted at the boundary, so single-precision factors give an approximate solve that
// the caller refines in double (linalg/crack_zone_solver.hpp).
enum class FactorPrecision { Double, Single };

class SchurFactorization {
 public:
  explicit SchurFactorization(FactorPrecision precision = FactorPrecision::Double);
  ~SchurFactorization();
  SchurFactorization(const SchurFactorization&) = delete;
  SchurFactorization& operator=(const SchurFactorization&) = delete;

  FactorPrecision precision() const { return precision_; }
  // Another precision from the next factorize() on (drops the present factors).
  void setPrecision(FactorPrecision precision);

  // Factorizes D A D (D = diag(scale); A square, its pattern fixed for the lifetime of this object) with
  // `schurUnknowns` (ascending, possibly empty) eliminated last, in the order `position` (the pivot
  // position of each unknown, the Schur unknowns last). A is read during this call only. The analysis is
  // repeated only when the set or the order changes. S and the solves below are those of D A D.
  void factorize(const CsrMatrix& A, std::span<const double> scale, const std::vector<std::int64_t>& schurUnknowns,
                 const std::vector<std::int32_t>& position);

  // S, column-major, size |Z| x |Z|.
  const std::vector<double>& schurComplement() const;
  std::vector<double> takeSchurComplement();
  // Entries of the sparse factors of the last factorization (MUMPS' INFOG(29), or the LU's own count).
  std::int64_t factorEntries() const;

  // First half of a solve: the reduced right-hand side b_Z - A_ZF A_FF^-1 b_F (size |Z|). The solver keeps
  // the forward-eliminated b for expand().
  void condense(std::span<const double> b, std::span<double> reduced);
  // Second half: given x_Z, the full solution x (x_Z in its place).
  void expand(std::span<const double> xZ, std::span<double> x);
  // Plain solve when Z is empty.
  void solve(std::span<const double> b, std::span<double> x);

  class Backend;  // one MUMPS instance of either precision (the .cpp)

 private:
  FactorPrecision precision_;
  std::unique_ptr<Backend> backend_;
};

}  // namespace peristep
