#pragma once
// Idle worker threads of OpenMP (libgomp) and OpenBLAS spin before they sleep: libgomp for up to 300k
// iterations after each parallel region, OpenBLAS for 2^28 cycles (with sched_yield) after each BLAS call.
// The fracture drivers alternate short OpenMP loops with MUMPS and BLAS calls, so on two cores the spinning
// threads take the CPU from the working ones (bench/README.md, "Issue 14, session 8": h = 8 um, f = 0.2,
// user + system time 57 -> 37 s). Both libraries read these settings only from the environment, when they
// are loaded: the host sets them before it opens the FMU; a program linked with them must re-execute.
#include <cstdlib>

namespace peristep {

// Asks for sleeping idle threads unless the user set the variables; true if it set any.
inline bool preferSleepingIdleThreads() {
  bool set = false;
  for (const auto& [name, value] : {std::pair{"OMP_WAIT_POLICY", "passive"}, std::pair{"OPENBLAS_THREAD_TIMEOUT", "4"}})
    if (!std::getenv(name)) {
      setenv(name, value, 0);
      set = true;
    }
  return set;
}

}  // namespace peristep
