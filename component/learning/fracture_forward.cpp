#include "learning/fracture_forward.hpp"

#include <cmath>

#include "core/byte_stream.hpp"
#include "core/errors.hpp"

namespace peristep::learning {

FractureStepper::FractureStepper(const DamagedLpsOperator& op, const FractureDrive& d, double s0, double dt)
    : op_(op), drive_(d), s0_(s0), dt_(dt) {
  const std::size_t n = op.grid().size();
  require(d.rho.size() == n && d.prescribed.size() == n && d.u0.size() == 2 * n && d.u1.size() == 2 * n,
          "fracture run: drive and grid differ");
  u_ = d.u0;
  maxStretch_ = d.initialStretch;
  op.updateMaxStretch(u_, maxStretch_);
  b_.assign(2 * n, 0.0);
  given_.assign(2 * n, 0.0);
}

bool FractureStepper::advance() {
  const std::size_t n = op_.grid().size();
  if (step_ == 0) {
    next_ = drive_.u1;  // u^1 is given (003 Sec. 3.1)
  } else {
    const double t = static_cast<double>(step_) * dt_;
    const std::vector<double> L = op_.apply(u_, maxStretch_, s0_);
    if (drive_.body) drive_.body(t, b_);
    next_.resize(2 * n);
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t c = 0; c < 2; ++c) {
        const std::size_t i = 2 * p + c;
        next_[i] = 2.0 * u_[i] - prev_[i] + dt_ * dt_ * (b_[i] - L[i]) / drive_.rho[p];  // 003:(29), (21)
      }
    if (drive_.boundary) {
      drive_.boundary(t + dt_, given_);  // prescribed points: u_D at t^{n+1}
      for (std::size_t p = 0; p < n; ++p)
        if (drive_.prescribed[p]) next_[2 * p] = given_[2 * p], next_[2 * p + 1] = given_[2 * p + 1];
    }
    for (const double x : next_)
      if (!std::isfinite(x)) return false;
  }
  prev_.swap(u_);
  u_.swap(next_);
  ++step_;
  op_.updateMaxStretch(u_, maxStretch_);  // 003:(28): max over m <= n
  return true;
}

std::vector<std::uint8_t> FractureStepper::saveState() const {
  ByteWriter w;
  w.put<std::uint64_t>(step_);
  w.putArray(u_);
  w.putArray(prev_);
  w.putArray(maxStretch_);
  return w.take();
}

void FractureStepper::restoreState(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes);
  const auto step = r.get<std::uint64_t>();
  auto u = r.getArray<double>(u_.size());
  auto prev = r.getArray<double>();
  auto smax = r.getArray<double>(maxStretch_.size());
  r.expectEnd();
  step_ = static_cast<std::size_t>(step);
  u_ = std::move(u);
  prev_ = std::move(prev);
  maxStretch_ = std::move(smax);
}

FractureRun runFracture(const DamagedLpsOperator& op, const FractureDrive& d, double s0, double dt,
                        std::size_t steps, std::size_t every) {
  require(every >= 1 && steps >= 1, "fracture run: at least one step, recorded every >= 1");
  FractureStepper stepper(op, d, s0, dt);
  FractureRun run;
  run.u.push_back(stepper.u());
  run.maxStretch.push_back(stepper.maxStretch());
  for (std::size_t step = 1; step <= steps; ++step) {
    if (!stepper.advance()) {
      run.finite = false;
      return run;
    }
    if (step % every == 0) run.u.push_back(stepper.u()), run.maxStretch.push_back(stepper.maxStretch());
  }
  return run;
}

}  // namespace peristep::learning
