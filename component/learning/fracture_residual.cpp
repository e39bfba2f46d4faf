#include "learning/fracture_residual.hpp"

#include <utility>

#include "core/errors.hpp"

namespace peristep::learning {

void subtractFrame0(FractureFrames& data) {
  for (std::size_t f = data.u.size(); f-- > 0;)
    for (std::size_t k = 0; k < data.u[f].size(); ++k) data.u[f][k] -= data.u[0][k];
}

FractureResidual::FractureResidual(FractureFrames data, DamagedLpsOperator op, std::size_t first, std::size_t last,
                                   double margin, std::vector<double> initialStretch)
    : data_(std::move(data)), op_(std::move(op)), first_(first), last_(last) {
  const CoarseGrid& g = data_.grid;
  require(first >= 1 && last + 1 < data_.u.size() && first <= last, "fracture residual: frames out of range");
  require(g.nx == op_.grid().nx && g.ny == op_.grid().ny, "fracture residual: frames and operator grids differ");
  const double xlo = g.x0 - 0.5 * g.hx, xhi = g.x0 + (static_cast<double>(g.nx) - 0.5) * g.hx;
  const double ylo = g.y0 - 0.5 * g.hy, yhi = g.y0 + (static_cast<double>(g.ny) - 0.5) * g.hy;
  for (std::size_t p = 0; p < g.size(); ++p)
    if (g.x(p) >= xlo + margin - 1e-9 && g.x(p) <= xhi - margin + 1e-9 && g.y(p) >= ylo + margin - 1e-9 &&
        g.y(p) <= yhi - margin + 1e-9)
      rows_.push_back(p);
  require(!rows_.empty(), "fracture residual: no point lies the margin inside the grid");
  std::vector<double> smax = std::move(initialStretch);
  for (const std::vector<double>& u : data_.u) {
    op_.updateMaxStretch(u, smax);
    maxStretch_.push_back(smax);
  }
}

double FractureResidual::loss(double s0) const {
  double total = 0.0;
  const double dt2 = data_.interval * data_.interval;
  for (std::size_t f = first_; f <= last_; ++f) {
    const std::vector<double> L = op_.apply(data_.u[f], maxStretch_[f], s0);
    for (const std::size_t p : rows_)
      for (int c = 0; c < 2; ++c) {
        const std::size_t i = 2 * p + static_cast<std::size_t>(c);
        const double acc = (data_.u[f + 1][i] - 2.0 * data_.u[f][i] + data_.u[f - 1][i]) / dt2;  // 003:(21)
        const double r = data_.rho[p] * acc + L[i] - data_.b[f][i];
        total += r * r;
      }
  }
  return total;
}

}  // namespace peristep::learning
