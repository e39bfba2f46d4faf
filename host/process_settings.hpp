#pragma once
// Settings that libraries read from the environment only when they are loaded or the process starts:
// - Idle worker threads of OpenMP (libgomp) and OpenBLAS spin before they sleep: libgomp for up to 300k
//   iterations after each parallel region, OpenBLAS for 2^28 cycles (with sched_yield) after each BLAS call.
//   The fracture drivers alternate short OpenMP loops with MUMPS and BLAS calls, so on two cores the spinning
//   threads take the CPU from the working ones (h = 8 um, f = 0.2: user + system time 57 -> 37 s;
//   docs/decisions/0012-process-settings-and-memory.md).
// - glibc's malloc on transparent huge pages (glibc >= 2.35): the crack zone allocates arrays of tens to
//   hundreds of MB afresh at every factorization (its own and MUMPS'), and with 4 KiB pages the first touch
//   of each page is a fault (h = 4 um, f = 0.8: 4.4 million faults; with huge pages 0.26 million and 14% less
//   wall time; docs/decisions/0012-process-settings-and-memory.md). The component itself leaves the importer's
//   allocator alone; the programs that own the process ask for it.
// - OpenBLAS' kernels: Debian 12's OpenBLAS 0.3.21 picks them by CPU model and falls back to its SSE3 (Prescott)
//   kernels on models it does not know (Intel Xeon model 207: sgemm at n = 2000 on two cores 65 GFlop/s, with
//   SkylakeX' kernels 318; docs/decisions/0006-openblas-kernels-by-cpu.md). The kernels are chosen here by the CPU's
//   features, as later OpenBLAS releases do for models they do not know.
// The program starts itself afresh when this set anything (glibc reads its tunables at start).
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <utility>

namespace peristep {

// The OpenBLAS kernel set for this CPU's vector units, or nullptr to leave the choice to OpenBLAS.
inline const char* openBlasKernelsForCpu() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512cd"))
    return "SkylakeX";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return __builtin_cpu_is("amd") ? "Zen" : "Haswell";
  return nullptr;
}

// Sets the variables the user did not set; true if it set any.
inline bool preferProcessSettings() {
  bool set = false;
  for (const auto& [name, value] : {std::pair{"OMP_WAIT_POLICY", "passive"}, std::pair{"OPENBLAS_THREAD_TIMEOUT", "4"},
                                    std::pair{"GLIBC_TUNABLES", "glibc.malloc.hugetlb=1"},
                                    std::pair{"OPENBLAS_CORETYPE", openBlasKernelsForCpu()}})
    if (value && !std::getenv(name)) {
      setenv(name, value, 0);
      set = true;
    }
  return set;
}

// The component's OpenMP thread count: libgomp reads it from the environment when the FMU loads it, so
// this must come before the FMU is loaded. Overrides the user's environment: it is the user's explicit
// choice on the command line.
inline void setThreadCount(unsigned threads) { setenv("OMP_NUM_THREADS", std::to_string(threads).c_str(), 1); }

// Sample studies run OpenBLAS on one thread unless the user chose otherwise: its results change in the
// last bits with its thread count (dgemm, dgemv and dtrsm alike), while the component's own loops give the
// same bits on any number of threads. So a sample is the same on one thread or two and under mpirun, and
// statistics of outputs that do not depend on xi have a standard deviation of 0; a study gains its speed
// from samples in parallel processes (docs/decisions/0020-serial-openblas.md). Before the FMU is loaded.
inline void preferSerialBlas() { setenv("OPENBLAS_NUM_THREADS", "1", 0); }

// At the top of main, before anything reads them: the settings above, then the program afresh with them
// (if that fails it goes on as it is, only slower).
inline void startWithProcessSettings(char** argv) {
  if (preferProcessSettings()) execv("/proc/self/exe", argv);
}

}  // namespace peristep
