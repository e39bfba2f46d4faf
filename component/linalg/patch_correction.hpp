#pragma once
// A local correction for the crack-zone solver M once rows change beyond its zone (linalg/crack_zone_solver.hpp).
// M then differs from A only in those rows R, and M^-1 leaves its error around them. The points owning R, grown
// by a few horizons, form a patch P; the patch's block of A (a sparse LU) is applied before and after M, a
// multiplicative Schwarz step (E: extension from the patch by zeros):
//   x = E A_PP^-1 E^T v,   x += M^-1 (v - A x),   x += E A_PP^-1 E^T (v - A x).
// The products with A touch the patch and the horizon around it only. As GMRES' preconditioner it takes away
// iterations and with them zones (docs/decisions/0010-patch-correction.md).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "core/csr_matrix.hpp"
#include "geometry/dof_map.hpp"
#include "geometry/neighbours.hpp"

namespace peristep {

class PatchCorrection {
 public:
  PatchCorrection(const Neighbours& nb, const DofMap& dofs);
  ~PatchCorrection();
  PatchCorrection(const PatchCorrection&) = delete;
  PatchCorrection& operator=(const PatchCorrection&) = delete;

  // The patch of the points owning `rows`, grown by `horizons` neighbourhoods, for D A D (D = diag(scale));
  // none when rows is empty, the patch has more than maxUnknowns unknowns or its block is singular. A and scale
  // must not change until the next build().
  void build(const CsrMatrix& A, std::span<const double> scale, std::span<const std::int64_t> rows, int horizons,
             std::size_t maxUnknowns);
  // Frees the patch and its LU.
  void clear();
  bool active() const { return !patchRows_.empty(); }
  // The patch's unknowns, ascending.
  const std::vector<std::int64_t>& rows() const { return patchRows_; }

  using Solve = std::function<void(std::span<const double>, std::span<double>)>;
  // out = the Schwarz step above applied to v, with M^-1 given as `solveM`.
  void apply(std::span<const double> v, std::span<double> out, const Solve& solveM);

 private:
  // (D A D x)_r for x given on the patch (local order).
  double rowTimesPatch(std::size_t r, const double* x) const;
  void solvePatch();  // patchOut_ = A_PP^-1 patchIn_
  void dropPatch();   // no patch (the LU and its ordering stay)

  const Neighbours& nb_;
  const DofMap& dofs_;
  std::vector<std::int32_t> rowPoint_;  // per unknown: the point it belongs to
  const CsrMatrix* A_ = nullptr;
  std::span<const double> scale_;
  std::vector<std::int64_t> patchRows_, haloRows_;  // ascending; halo: the rows that reach into the patch
  std::vector<std::int32_t> local_;                 // per unknown: position in patchRows_, -1 outside
  struct Lu;
  std::unique_ptr<Lu> lu_;  // of the patch's block of D A D
  std::vector<std::int64_t> analyzedRows_;  // the patch whose block's ordering lu_ holds
  std::vector<double> residual_, patchIn_, patchOut_;
};

}  // namespace peristep
