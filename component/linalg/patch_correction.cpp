#include "linalg/patch_correction.hpp"

#include <Eigen/SparseLU>
#include <algorithm>

namespace peristep {

struct PatchCorrection::Lu {
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
};

PatchCorrection::PatchCorrection(const Neighbours& nb, const DofMap& dofs)
    : nb_(nb),
      dofs_(dofs),
      rowPoint_(static_cast<std::size_t>(dofs.size), -1),
      local_(rowPoint_.size(), -1),
      lu_(std::make_unique<Lu>()) {
  for (std::size_t p = 0; p < dofs_.u.size(); ++p)
    dofs_.forEachRow(p, [&](std::int64_t r) { rowPoint_[static_cast<std::size_t>(r)] = static_cast<std::int32_t>(p); });
}

PatchCorrection::~PatchCorrection() = default;

void PatchCorrection::dropPatch() {
  for (std::int64_t r : patchRows_) local_[static_cast<std::size_t>(r)] = -1;
  patchRows_.clear();
  haloRows_.clear();
}

void PatchCorrection::clear() {
  dropPatch();
  lu_ = std::make_unique<Lu>();
  analyzedRows_.clear();
}

void PatchCorrection::solvePatch() {
  const auto m = static_cast<Eigen::Index>(patchRows_.size());
  Eigen::Map<Eigen::VectorXd>(patchOut_.data(), m) =
      lu_->lu.solve(Eigen::Map<const Eigen::VectorXd>(patchIn_.data(), m));
}

void PatchCorrection::build(const CsrMatrix& A, std::span<const double> scale, std::span<const std::int64_t> rows,
                            int horizons, std::size_t maxUnknowns) {
  dropPatch();
  if (rows.empty()) return;
  A_ = &A;
  scale_ = scale;
  // Breadth-first over the neighbour lists: level 1 marks the patch, the last level the halo around it (the
  // rows of A reach one horizon).
  std::vector<std::uint8_t> level(dofs_.u.size(), 0);
  std::vector<std::size_t> frontier, points;
  for (std::int64_t r : rows) {
    const auto p = static_cast<std::size_t>(rowPoint_[static_cast<std::size_t>(r)]);
    if (!level[p]) {
      level[p] = 1;
      frontier.push_back(p);
    }
  }
  points = frontier;
  for (int step = 0; step <= horizons; ++step) {
    const std::uint8_t mark = step == horizons ? 2 : 1;
    std::vector<std::size_t> next;
    for (std::size_t p : frontier)
      for (std::size_t k = nb_.begin(p); k < nb_.end(p); ++k) {
        const std::size_t q = nb_.index[k];
        if (level[q]) continue;
        level[q] = mark;
        next.push_back(q);
      }
    points.insert(points.end(), next.begin(), next.end());
    frontier = std::move(next);
  }
  std::sort(points.begin(), points.end());
  for (std::size_t p : points)
    dofs_.forEachRow(p, [&](std::int64_t r) {
      haloRows_.push_back(r);
      if (level[p] == 1) patchRows_.push_back(r);
    });
  if (patchRows_.size() > maxUnknowns) {
    dropPatch();
    return;
  }
  for (std::size_t i = 0; i < patchRows_.size(); ++i)
    local_[static_cast<std::size_t>(patchRows_[i])] = static_cast<std::int32_t>(i);

  // The patch's block of D A D. A's pattern is fixed, so the same patch has the same block pattern: its
  // ordering (COLAMD) is kept for the next build of that patch.
  const std::size_t m = patchRows_.size();
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t i = 0; i < m; ++i) {
    const auto r = static_cast<std::size_t>(patchRows_[i]);
    for (auto k = static_cast<std::size_t>(A.rowStart[r]); k < static_cast<std::size_t>(A.rowStart[r + 1]); ++k) {
      const auto c = static_cast<std::size_t>(A.col[k]);
      if (local_[c] >= 0) entries.emplace_back(static_cast<int>(i), local_[c], scale[r] * A.value[k] * scale[c]);
    }
  }
  Eigen::SparseMatrix<double> block(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  block.setFromTriplets(entries.begin(), entries.end());
  if (patchRows_ != analyzedRows_) {
    lu_->lu.analyzePattern(block);
    analyzedRows_ = patchRows_;
  }
  lu_->lu.factorize(block);
  if (lu_->lu.info() != Eigen::Success) {
    dropPatch();  // M alone then: GMRES converges without the correction, only slower
    return;
  }
  residual_.resize(scale.size());
  patchIn_.resize(m);
  patchOut_.resize(m);
}

double PatchCorrection::rowTimesPatch(std::size_t r, const double* x) const {
  double sum = 0;
  for (auto k = static_cast<std::size_t>(A_->rowStart[r]); k < static_cast<std::size_t>(A_->rowStart[r + 1]); ++k) {
    const auto c = static_cast<std::size_t>(A_->col[k]);
    if (local_[c] >= 0) sum += A_->value[k] * scale_[c] * x[local_[c]];
  }
  return scale_[r] * sum;
}

void PatchCorrection::apply(std::span<const double> v, std::span<double> out, const Solve& solveM) {
  if (!active()) {
    solveM(v, out);
    return;
  }
  const std::size_t m = patchRows_.size();
  for (std::size_t i = 0; i < m; ++i) patchIn_[i] = v[static_cast<std::size_t>(patchRows_[i])];
  solvePatch();
  std::copy(v.begin(), v.end(), residual_.begin());
  for (std::int64_t r : haloRows_)
    residual_[static_cast<std::size_t>(r)] -= rowTimesPatch(static_cast<std::size_t>(r), patchOut_.data());
  solveM(residual_, out);
  for (std::size_t i = 0; i < m; ++i) out[static_cast<std::size_t>(patchRows_[i])] += patchOut_[i];
  // The patch rows of v - A out (out is now nonzero everywhere: whole rows).
  for (std::size_t i = 0; i < m; ++i) {
    const auto r = static_cast<std::size_t>(patchRows_[i]);
    double sum = 0;
    for (auto k = static_cast<std::size_t>(A_->rowStart[r]); k < static_cast<std::size_t>(A_->rowStart[r + 1]); ++k) {
      const auto c = static_cast<std::size_t>(A_->col[k]);
      sum += A_->value[k] * scale_[c] * out[c];
    }
    patchIn_[i] = v[r] - scale_[r] * sum;
  }
  solvePatch();
  for (std::size_t i = 0; i < m; ++i) out[static_cast<std::size_t>(patchRows_[i])] += patchOut_[i];
}

}  // namespace peristep
