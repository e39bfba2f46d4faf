#pragma once
// Peak resident memory of this process, read from /proc (Linux).
#include <cstddef>

namespace peristep {

// Peak resident set size in bytes since start or since the last resetPeakMemory().
std::size_t peakMemoryBytes();
// Restart the peak count (Linux >= 4.0); returns false where the kernel does not allow it.
bool resetPeakMemory();

}  // namespace peristep
