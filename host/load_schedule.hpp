#pragma once
// The communication steps of a loading scenario: one fmi3DoStep per load increment.
#include <cstdint>
#include <vector>

#include "scene_file.hpp"

namespace peristep::host {

struct Increment {
  std::uint64_t index = 0;  // 1-based
  double time = 0;          // communication point at the start of the step
  double stepSize = 0;
  double input = 0;         // value the ramped input holds during the step (unused without an input)
};

// Increment k of n spans [t0 + (k-1) dt, t0 + k dt] with dt = (stop - start) / n and holds the input
// at from + k (to - from) / n: a quasi-static step solves at the load reached at its end.
std::vector<Increment> loadSchedule(const Loading& loading);

}  // namespace peristep::host
