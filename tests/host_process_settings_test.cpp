// The host and the benchmarks ask libgomp and OpenBLAS for sleeping idle threads and glibc's malloc for huge
// pages (host/process_settings.hpp), but a value the user set wins.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "process_settings.hpp"

TEST_CASE("the host asks for sleeping idle threads and huge pages unless the user chose otherwise", "[host]") {
  unsetenv("OPENBLAS_THREAD_TIMEOUT");
  setenv("OMP_WAIT_POLICY", "active", 1);
  setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=0", 1);
  CHECK(peristep::preferProcessSettings());
  CHECK(std::string(std::getenv("OMP_WAIT_POLICY")) == "active");
  CHECK(std::string(std::getenv("OPENBLAS_THREAD_TIMEOUT")) == "4");
  CHECK(std::string(std::getenv("GLIBC_TUNABLES")) == "glibc.malloc.hugetlb=0");
  CHECK_FALSE(peristep::preferProcessSettings());  // all set now: nothing to do, no re-execution
  unsetenv("OMP_WAIT_POLICY");
  unsetenv("GLIBC_TUNABLES");
  CHECK(peristep::preferProcessSettings());
  CHECK(std::string(std::getenv("OMP_WAIT_POLICY")) == "passive");
  CHECK(std::string(std::getenv("GLIBC_TUNABLES")) == "glibc.malloc.hugetlb=1");
}
