// Catch's main, started with the OpenBLAS kernels the host chooses for the CPU (host/process_settings.hpp), so
// that the tests run the kernels a user of the host runs (the SSE3 fall-back of Debian 12's OpenBLAS on CPU models
// it does not know rounds differently; tests/CMakeLists.txt runs the test it once failed with those kernels).
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
