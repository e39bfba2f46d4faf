#pragma once
// The discrete heterogeneous LPS system in (u, theta), 000:(3.1)-(3.2) with the sign of 000:(2.5).
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "core/csr_matrix.hpp"
#include "geometry/dof_map.hpp"
#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"

namespace peristep {

// Scaled kernel 000:(4.2), normalized so that int K z z^T dz = I (theta = div u for linear u).
inline double lpsKernel(double r, double delta) { return 3.0 / (std::numbers::pi * delta * delta * delta * r); }

// The unknowns of 000:(3.1)-(3.2) (geometry/dof_map.hpp) for a cloud and its neighbour lists.
DofMap numberDofs(const PointCloud& cloud, const Neighbours& nb);

// The linear system A x = b - B g, where g holds the prescribed displacements of all points
// (g[2p], g[2p+1]); B has one column per point component and is zero on unknown components.
struct LpsSystem {
  CsrMatrix A;  // unknown columns
  CsrMatrix B;  // prescribed columns (size dofs x 2*points)
};

// lambda, mu: per point (collar included); w: quadrature weights aligned with nb.
// intact: bond state gamma per CSR entry (000:(3.17)), or null when nothing can break. With it, the
// corrected dilatation 000:(3.20)-(3.21) applies at every point that has a broken bond, and the
// free-surface terms of 000:(3.19), (3.22) wherever no free surface ends inside the horizon. Bonds to Void
// points add no entries; other broken bonds keep (zero) entries, so the sparsity pattern, and with it the
// symbolic factorization, never changes while bonds break.
LpsSystem assembleLps(const PointCloud& cloud, const Neighbours& nb, const std::vector<double>& w,
                      const std::vector<double>& lambda, const std::vector<double>& mu, const DofMap& dofs,
                      const std::vector<std::uint8_t>* intact = nullptr);

// Recomputes the rows of `points` (u and theta) of s = assembleLps(..., &intact) in place: the values the
// full assembly would give, bit for bit, at a cost proportional to the points (the fracture driver
// updates the rows around newly broken bonds instead of reassembling).
void reassembleLpsRows(const PointCloud& cloud, const Neighbours& nb, const std::vector<double>& w,
                       const std::vector<double>& lambda, const std::vector<double>& mu, const DofMap& dofs,
                       const std::vector<std::uint8_t>& intact, std::span<const std::size_t> points, LpsSystem& s);

}  // namespace peristep
