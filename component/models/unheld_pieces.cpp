#include "models/unheld_pieces.hpp"

#include <numeric>

namespace peristep {

namespace {

std::size_t root(std::vector<std::size_t>& parent, std::size_t p) {
  while (parent[p] != p) p = parent[p] = parent[parent[p]];  // path halving
  return p;
}

}  // namespace

std::vector<std::size_t> unheldPoints(const PointCloud& c, const Neighbours& nb, const std::vector<std::uint8_t>* intact) {
  std::vector<std::size_t> parent(c.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (c.isVoid(p)) continue;
    for (std::size_t k = nb.begin(p); k < nb.end(p); ++k) {
      const std::size_t q = nb.index[k];
      if (c.isVoid(q) || (intact && !(*intact)[k])) continue;
      parent[root(parent, p)] = root(parent, q);
    }
  }
  std::vector<char> held(c.size(), 0);
  for (std::size_t p = 0; p < c.size(); ++p)
    if (!c.isVoid(p) && !c.inDomain(p)) held[root(parent, p)] = 1;
  std::vector<std::size_t> unheld;
  for (std::size_t p : c.domain)
    if (!held[root(parent, p)]) unheld.push_back(p);
  return unheld;
}

void holdAtRest(CsrMatrix& A, const DofMap& dofs, const std::vector<std::size_t>& points) {
  if (points.empty()) return;
  std::vector<char> fixed(static_cast<std::size_t>(A.cols), 0);
  for (std::size_t p : points) {
    const auto k = static_cast<std::size_t>(dofs.u[p]);
    fixed[k] = fixed[k + 1] = 1;
  }
  for (std::int64_t r = 0; r < A.rows; ++r) {
    const bool row = fixed[static_cast<std::size_t>(r)];
    for (std::int64_t k = A.rowStart[r]; k < A.rowStart[r + 1]; ++k) {
      const std::int64_t j = A.col[k];
      if (row && j == r) {
        if (A.value[k] == 0.0) A.value[k] = 1.0;  // a point whose bonds are all broken
      } else if (row || fixed[static_cast<std::size_t>(j)]) {
        A.value[k] = 0.0;
      }
    }
  }
}

}  // namespace peristep
