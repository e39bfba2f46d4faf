#include "core/memory.hpp"

#include <fstream>
#include <string>

namespace peristep {

std::size_t peakMemoryBytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      std::size_t kib = 0;
      status >> kib;
      return kib * 1024;
    }
    status.ignore(4096, '\n');
  }
  return 0;
}

bool resetPeakMemory() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";  // "5" resets the peak RSS counter, see proc(5)
  return static_cast<bool>(clear.flush());
}

}  // namespace peristep
