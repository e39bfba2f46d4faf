// Starts as the host does (host/process_settings.hpp), then loads OpenBLAS and checks that it runs the kernels
// chosen for this CPU, not the SSE3 ones Debian 12's OpenBLAS falls back to on CPU models it does not know.
// Exit code 0 when it does (or when the CPU has no AVX2, where OpenBLAS chooses), 1 otherwise.
#include <dlfcn.h>
#include <strings.h>

#include <cstdio>
#include <cstdlib>

#include "process_settings.hpp"

int main(int, char** argv) {
  const bool userChose = std::getenv("OPENBLAS_CORETYPE") != nullptr;
  peristep::startWithProcessSettings(argv);
  void* blas = dlopen("libopenblas.so.0", RTLD_NOW | RTLD_LOCAL);
  if (!blas) {
    std::fprintf(stderr, "cannot load OpenBLAS: %s\n", dlerror());
    return 1;
  }
  using CoreName = const char* (*)();
  const auto coreName = reinterpret_cast<CoreName>(dlsym(blas, "openblas_get_corename"));
  if (!coreName) return std::fprintf(stderr, "libopenblas.so.0 has no openblas_get_corename\n"), 1;
  const char* wanted = userChose ? std::getenv("OPENBLAS_CORETYPE") : peristep::openBlasKernelsForCpu();
  std::printf("kernels wanted %s, OpenBLAS runs %s\n", wanted ? wanted : "(OpenBLAS' choice)", coreName());
  return !wanted || strcasecmp(wanted, coreName()) == 0 ? 0 : 1;
}
