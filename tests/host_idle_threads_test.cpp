// The host asks libgomp and OpenBLAS for sleeping idle threads (host/idle_threads.hpp), but a value the
// user set wins.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "idle_threads.hpp"

TEST_CASE("the host asks for sleeping idle threads unless the user chose a policy", "[host]") {
  unsetenv("OPENBLAS_THREAD_TIMEOUT");
  setenv("OMP_WAIT_POLICY", "active", 1);
  CHECK(peristep::preferSleepingIdleThreads());
  CHECK(std::string(std::getenv("OMP_WAIT_POLICY")) == "active");
  CHECK(std::string(std::getenv("OPENBLAS_THREAD_TIMEOUT")) == "4");
  CHECK_FALSE(peristep::preferSleepingIdleThreads());  // both set now: nothing to do, no re-execution
  unsetenv("OMP_WAIT_POLICY");
  CHECK(peristep::preferSleepingIdleThreads());
  CHECK(std::string(std::getenv("OMP_WAIT_POLICY")) == "passive");
}
