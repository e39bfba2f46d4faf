#pragma once
// How long work tells its caller how far it has come: `done` of `total` units of a named phase
// (realizations, internal time steps, ...). The solver calls it from the thread that called it, never
// from an OpenMP worker, so a receiver needs no locking; the FMI layer turns it into log messages.
#include <cstdint>
#include <functional>
#include <string_view>

namespace peristep {

using ProgressHook = std::function<void(std::string_view phase, std::uint64_t done, std::uint64_t total)>;

// Calls hook (when set) at most `reports` times over a run of `total` units, plus once at the end.
class ProgressReporter {
 public:
  ProgressReporter(const ProgressHook& hook, std::string_view phase, std::uint64_t total, std::uint64_t reports = 20)
      : hook_(hook), phase_(phase), total_(total), stride_(total / (reports ? reports : 1) + 1) {}
  void operator()(std::uint64_t done) {
    if (!hook_ || (done < total_ && done < next_)) return;
    next_ = done + stride_;
    hook_(phase_, done, total_);
  }

 private:
  const ProgressHook& hook_;
  std::string_view phase_;
  std::uint64_t total_, stride_, next_ = 0;
};

}  // namespace peristep
