#include "learning/fracture_forward.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace peristep::learning {

FractureRun runFracture(const DamagedLpsOperator& op, const FractureDrive& d, double s0, double dt,
                        std::size_t steps, std::size_t every) {
  const std::size_t n = op.grid().size();
  require(d.rho.size() == n && d.prescribed.size() == n && d.u0.size() == 2 * n && d.u1.size() == 2 * n &&
              every >= 1 && steps >= 1,
          "fracture run: drive and grid differ");
  FractureRun run;
  std::vector<double> prev = d.u0, u = d.u1, next(2 * n), b(2 * n, 0.0), given(2 * n, 0.0), smax = d.initialStretch;
  op.updateMaxStretch(prev, smax);
  run.u.push_back(prev);
  run.maxStretch.push_back(smax);
  for (std::size_t step = 1; step <= steps; ++step) {
    op.updateMaxStretch(u, smax);  // 003:(28): max over m <= n
    if (step % every == 0) run.u.push_back(u), run.maxStretch.push_back(smax);
    if (step == steps) break;
    const double t = static_cast<double>(step) * dt;
    const std::vector<double> L = op.apply(u, smax, s0);
    if (d.body) d.body(t, b);
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t c = 0; c < 2; ++c) {
        const std::size_t i = 2 * p + c;
        next[i] = 2.0 * u[i] - prev[i] + dt * dt * (b[i] - L[i]) / d.rho[p];  // 003:(29), (21)
      }
    if (d.boundary) {
      d.boundary(t + dt, given);  // prescribed points: u_D at t^{n+1}
      for (std::size_t p = 0; p < n; ++p)
        if (d.prescribed[p]) next[2 * p] = given[2 * p], next[2 * p + 1] = given[2 * p + 1];
    }
    prev.swap(u);
    u.swap(next);
    for (const double x : u)
      if (!std::isfinite(x)) {
        run.finite = false;
        return run;
      }
  }
  return run;
}

}  // namespace peristep::learning
