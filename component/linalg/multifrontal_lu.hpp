#pragma once
// Multifrontal sparse LU in single precision without pivoting, with a set of unknowns Z eliminated last
// (their dense Schur complement is the result, not factored). The pattern is taken as that of A + A^T; the
// values may be unsymmetric. Written for the fracture driver's scaled stiffness D A D, whose pivots MUMPS
// never delayed and whose crack is the same without pivoting (docs/decisions/0001-own-single-precision-lu.md); a zero
// or non-finite pivot throws SolverFailure. The factors are stored front by front in the order the
// substitutions read them, so that a substitution streams them once.
#include <cstdint>
#include <span>
#include <vector>

#include "core/csr_matrix.hpp"

namespace peristep {

class MultifrontalLu {
 public:
  using Index = std::int32_t;

  // Symbolic phase: elimination tree of the pivot order `position` (Z = the last `schurCount` positions),
  // its postorder, supernodes (relaxed), their row lists and where A's entries go.
  void analyze(const CsrMatrix& A, const std::vector<std::int32_t>& position, std::size_t schurCount,
               const std::vector<std::int64_t>& schurUnknowns);
  // Numeric phase on D A D; S (column-major, |Z| x |Z|, in the order of `schurUnknowns`) into `schur`.
  void factorize(const CsrMatrix& A, std::span<const double> scale, std::vector<double>& schur);

  // b -> b_Z - A_ZF A_FF^-1 b_F (kept forward-eliminated for expand()).
  void condense(std::span<const double> b, std::span<double> reduced);
  // x_Z -> x.
  void expand(std::span<const double> xZ, std::span<double> x);
  // Z empty: x = A^-1 b.
  void solve(std::span<const double> b, std::span<double> x);

  std::int64_t factorEntries() const { return factorEntries_; }
  bool analyzed() const { return n_ > 0; }

 private:
  // The steps of analyze().
  std::vector<Index> labelInPostorder(const std::vector<Index>& treeParent, const std::vector<std::int32_t>& position,
                                      const std::vector<std::int64_t>& schurUnknowns);
  std::vector<Index> setSupernodes(const std::vector<Index>& parent, const std::vector<std::int64_t>& count);
  void placeEntries(const CsrMatrix& A, const std::vector<Index>& nodeOfColumn);
  void measureFronts();
  void forward();
  void backward();
  void splitForSubstitutions();
  void forwardNode(std::size_t s, float* w, std::vector<float>& f, float* outside, std::int8_t group) const;
  void backwardNode(std::size_t s, float* w, std::vector<float>& xb) const;
  void factorNode(std::size_t s, const std::vector<float>& value, std::vector<float>& front, std::vector<Index>& local,
                  std::int64_t& top);

  std::int64_t n_ = 0, nF_ = 0, z_ = 0;
  std::vector<std::int32_t> internal_;  // unknown -> internal index (postorder of the tree, Z last)
  // Supernode s: columns [first_[s], first_[s + 1]), rows rows_[rowStart_[s] .. rowStart_[s + 1]) (its
  // columns, then the rows below ascending), parent (-1: its contribution goes to S).
  std::vector<std::int32_t> first_, parent_, rows_;
  std::vector<std::int64_t> rowStart_, factorStart_;
  std::vector<std::int32_t> childStart_, children_;
  // A's entries, grouped by the supernode whose front receives them, with their offset in that front;
  // entries in Z x Z go to S.
  std::vector<std::int64_t> ownStart_;
  std::vector<Index> ownEntry_;  // fits: analyze() requires fewer than 2^31 entries
  std::vector<std::int32_t> ownOffset_;
  std::vector<std::int64_t> schurEntry_, schurOffset_;
  std::int64_t factorEntries_ = 0, maxFront_ = 0, stackPeak_ = 0;
  // The substitutions' split: two groups of whole subtrees, done in parallel, and the supernodes above them;
  // owner_ of each unknown: its group, or -1 (above, or Z).
  std::vector<Index> group_[2], above_;
  std::vector<std::int8_t> owner_;
  std::vector<float> factors_, work_, outside_;
  std::vector<float> stack_;  // during factorize(): the contribution blocks waiting for their parent
  std::vector<std::int64_t> place_;  // where a supernode's contribution block is on stack_
};

}  // namespace peristep
