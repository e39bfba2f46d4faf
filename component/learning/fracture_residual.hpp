#pragma once
// Damage-criterion learning step of 003 (Algorithm 1 (v)): with the kernel and moduli fixed, the equation
// residual 003:(42) of a fracture sample as a function of the critical stretch s0 alone (minimized by
// learning/critical_stretch_fit.hpp). The largest bond stretches do not depend on s0 and are found once, so a
// loss evaluation is one pass of L_KN per frame.
#include <cstddef>
#include <vector>

#include "learning/damaged_lps_operator.hpp"

namespace peristep::learning {

struct FractureFrames {
  CoarseGrid grid;                       // not periodic; hx = hy
  double interval = 0;                   // frame interval, in the time unit of rho and L (sqrt(amu A^2/eV))
  std::vector<double> rho;               // per point
  std::vector<std::vector<double>> u, b;  // per frame, interleaved (x, y)
};
// The frames minus frame 0: frame 0 as the unstressed reference state.
void subtractFrame0(FractureFrames& data);

class FractureResidual {
 public:
  // Residual rows: points whose horizon lies inside the grid by `margin` (003 Sec. 5.1 uses 2 delta), frames
  // first..last (central differences 003:(21) need first >= 1 and last + 1 < frames). initialStretch: the
  // largest stretches before frame 0 (e.g. DamagedLpsOperator::slit), empty for none.
  FractureResidual(FractureFrames data, DamagedLpsOperator op, std::size_t first, std::size_t last, double margin,
                   std::vector<double> initialStretch = {});
  // sum over frames and rows of |rho u'' + L_KN[u] - b|^2, 003:(42) (the constant Delta t / M dropped).
  double loss(double s0) const;
  // Largest stretch of every bond over frames 0..n.
  const std::vector<double>& maxStretch(std::size_t frame) const { return maxStretch_[frame]; }
  std::size_t rows() const { return rows_.size(); }

 private:
  FractureFrames data_;
  DamagedLpsOperator op_;
  std::size_t first_, last_;
  std::vector<std::size_t> rows_;
  std::vector<std::vector<double>> maxStretch_;  // per frame
};

}  // namespace peristep::learning
