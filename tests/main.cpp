// Catch's main, started with the OpenBLAS kernels the host chooses for the CPU (host/process_settings.hpp), so
// that the tests run the kernels a user of the host runs. The choice matters beyond speed: with the SSE3 kernels
// Debian 12's OpenBLAS falls back to on CPU models it does not know, the floating island's singular solve
// (tests/fmi_elastic_specimen_test.cpp) rounds to 0/0 and initialization is refused (session 43).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <unistd.h>

#include <cstdlib>

#include "../host/process_settings.hpp"

int main(int argc, char** argv) {
  if (const char* kernels = peristep::openBlasKernelsForCpu(); kernels && !std::getenv("OPENBLAS_CORETYPE")) {
    setenv("OPENBLAS_CORETYPE", kernels, 0);
    execv("/proc/self/exe", argv);  // OpenBLAS reads it when it loads; if this fails, the tests go on as they are
  }
  return Catch::Session().run(argc, argv);
}
