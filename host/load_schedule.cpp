#include "load_schedule.hpp"

namespace peristep::host {

std::vector<Increment> loadSchedule(const Loading& l) {
  std::vector<Increment> out;
  out.reserve(l.steps);
  const double n = static_cast<double>(l.steps);
  for (std::uint64_t k = 1; k <= l.steps; ++k) {
    // Both ends computed from k (not accumulated) so the last step lands exactly on stopTime and `to`.
    const double t0 = l.startTime + (l.stopTime - l.startTime) * static_cast<double>(k - 1) / n;
    const double t1 = k == l.steps ? l.stopTime : l.startTime + (l.stopTime - l.startTime) * static_cast<double>(k) / n;
    const double input = k == l.steps ? l.to : l.from + (l.to - l.from) * static_cast<double>(k) / n;
    out.push_back({k, t0, t1 - t0, input});
  }
  return out;
}

}  // namespace peristep::host
