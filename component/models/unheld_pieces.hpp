#pragma once
// Pieces of the specimen that nothing holds: sets of domain points joined by bonds to each other but by no
// bond to the collar (an island cut out by Void or pre-cracks). Their rigid motions are free, so the
// quasi-static system is singular there; an unloaded piece stays where it is (u = 0), and the rows of its
// displacement are replaced by that condition, so the solve no longer depends on how a zero pivot rounds.
#include <cstdint>
#include <vector>

#include "core/csr_matrix.hpp"
#include "geometry/neighbours.hpp"
#include "geometry/point_cloud.hpp"
#include "models/lps_system.hpp"

namespace peristep {

// The domain points of the pieces that no bond (intact, when given) connects to a collar point.
std::vector<std::size_t> unheldPoints(const PointCloud& c, const Neighbours& nb, const std::vector<std::uint8_t>* intact);

// Rows and columns of u at these points become u = 0 (diagonal kept, other entries zeroed; pattern unchanged).
void holdAtRest(CsrMatrix& A, const DofMap& dofs, const std::vector<std::size_t>& points);

}  // namespace peristep
