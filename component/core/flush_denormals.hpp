#pragma once
// Explicit dynamics spreads every disturbance one horizon per step, with amplitudes that fall below the
// smallest normal double (2.2e-308) long before a wave arrives; x86 arithmetic on such denormal numbers
// runs up to ~100x slower. They carry nothing physical, so the dynamics loops flush them to zero (FTZ,
// DAZ) while they run and give the thread its previous mode back afterwards: the component runs inside
// other programs, whose floating-point mode it must not change. Each OpenMP thread has its own mode, so a
// parallel region takes one guard per thread. Used in the bond loops and around central difference, not
// around SUNDIALS' own arithmetic: with the whole CVODE call flushed, BDF ended 1.6e-3 away from the
// reference work in the stiff-inclusion test (tests/dynamics_integrators_test.cpp; not traced further),
// while flushing only the force evaluations inside it changes nothing there.
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace peristep {

class FlushDenormals {
 public:
#if defined(__SSE2__)
  FlushDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
  ~FlushDenormals() { _mm_setcsr(saved_); }
#else
  FlushDenormals() = default;
#endif
  FlushDenormals(const FlushDenormals&) = delete;
  FlushDenormals& operator=(const FlushDenormals&) = delete;

 private:
#if defined(__SSE2__)
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;  // MXCSR bits
  unsigned saved_;
#endif
};

}  // namespace peristep
