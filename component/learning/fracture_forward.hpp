#pragma once
// Forward run of the learned LPS model with damage: central differences 003:(20)-(21) in the form (29), the
// operator L_KN^h of 003:(30)-(33) with the bond states (28) of the largest stretch so far (m <= n), points
// of BOmega_D prescribed. One explicit step per call of L_KN; the bond states are not iterated within a
// step (003 Sec. 5.2 re-solves a step until no new bond breaks; with steps far below the frame interval the
// states lag by one step only).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "learning/damaged_lps_operator.hpp"

namespace peristep::learning {

struct FractureDrive {
  std::vector<double> rho;                 // per point
  std::vector<char> prescribed;            // per point: displacement given (BOmega_D of 003:(29))
  std::vector<double> u0, u1;              // u at t = 0 and t = dt, 003 Sec. 3.1 (interleaved x, y)
  std::function<void(double t, std::vector<double>& u)> boundary;  // u_D at t (read at prescribed points)
  std::function<void(double t, std::vector<double>& b)> body;      // body force per volume at t (all points)
  std::vector<double> initialStretch;      // largest stretches before t = 0 (e.g. DamagedLpsOperator::slit)
};

struct FractureRun {
  std::vector<std::vector<double>> u;           // at steps 0, every, 2 every, ...
  std::vector<std::vector<double>> maxStretch;  // largest bond stretches up to each recorded step
  bool finite = true;                           // false: the run blew up (unstable step), stopped there
};

// The run one step at a time (an FMU steps it frame by frame): at step n it holds u^n, u^(n-1) and the
// largest stretches of steps 0..n. `op` and `drive` must outlive it.
class FractureStepper {
 public:
  FractureStepper(const DamagedLpsOperator& op, const FractureDrive& drive, double s0, double dt);
  // One step; false (and the state left as it was) when u^(n+1) is not finite: the step is unstable.
  bool advance();
  std::size_t step() const { return step_; }
  const std::vector<double>& u() const { return u_; }
  const std::vector<double>& maxStretch() const { return maxStretch_; }
  // The state after set-up: step, u^n, u^(n-1), largest stretches.
  std::vector<std::uint8_t> saveState() const;
  void restoreState(std::span<const std::uint8_t> bytes);

 private:
  const DamagedLpsOperator& op_;
  const FractureDrive& drive_;
  double s0_, dt_;
  std::size_t step_ = 0;
  std::vector<double> prev_, u_, next_, b_, given_, maxStretch_;
};

// `steps` steps of size dt from (u0, u1); records every `every`-th step (step 0 included).
FractureRun runFracture(const DamagedLpsOperator& op, const FractureDrive& drive, double s0, double dt,
                        std::size_t steps, std::size_t every);

}  // namespace peristep::learning
