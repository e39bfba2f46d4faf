#pragma once
// Peak resident memory of this process, read from /proc (Linux), and the memory it may use.
#include <cstddef>

namespace peristep {

// Empties a container and returns its storage to the allocator. (v = {} would not: for a std::vector it
// assigns an empty list and keeps the capacity, which held 1.2 GB of old factors through the next
// factorization at h = 2 um; docs/decisions/0012-process-settings-and-memory.md.)
template <class Container>
void freeStorage(Container& c) {
  Container().swap(c);
}

// Peak resident set size in bytes since start or since the last resetPeakMemory().
std::size_t peakMemoryBytes();
// Restart the peak count (Linux >= 4.0); returns false where the kernel does not allow it.
bool resetPeakMemory();
// Physical memory of the machine or this process's address-space limit (RLIMIT_AS), whichever is smaller.
std::size_t usableMemoryBytes();

}  // namespace peristep
