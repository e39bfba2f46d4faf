// An allocation that fails inside an OpenMP region (std::bad_alloc in the LPS assembly killed the
// importer with SIGABRT) reaches the caller as an exception, and the FMI functions turn it
// into fmi3Error with the one message "out of memory". This program replaces the global operator new:
// while armed, every allocation made by an OpenMP worker thread (not the calling thread: an exception
// there has no caller to go to) inside a parallel region throws.
#include <omp.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "fmi3Functions.h"
#include "models/lps_discretization.hpp"
#include "models/lps_material.hpp"
#include "peristep.h"

namespace {
std::atomic<bool> armed{false};
std::atomic<long> refused{0};

// Arms the failure for one scope, with a worker thread to fail in.
struct FailInParallel {
  FailInParallel() {
    omp_set_num_threads(2);
    armed = true;
  }
  ~FailInParallel() { armed = false; }
};
}  // namespace

void* operator new(std::size_t n) {
  if (armed.load(std::memory_order_relaxed) && omp_get_level() > 0 && omp_get_thread_num() > 0) {
    ++refused;
    throw std::bad_alloc();
  }
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace peristep;

TEST_CASE("a bad_alloc inside the parallel assembly leaves assembleLps as an exception", "[fmi][memory]") {
  const LpsDiscretization d = LpsDiscretization::build(GridSpec{17, 17, 1.0, 1.0, 3.0});
  const Lame l = planeStrain(1.0, 0.3);
  const std::vector<double> lambda(d.cloud.size(), l.lambda), mu(d.cloud.size(), l.mu);
  const long before = refused;
  {
    FailInParallel fail;
    CHECK_THROWS_AS(assembleLps(d.cloud, d.neighbours, d.weights, lambda, mu, d.dofs), std::bad_alloc);
  }
  CHECK(refused > before);  // the failure came from inside the region
  // and nothing is left broken: the same call succeeds afterwards
  CHECK(assembleLps(d.cloud, d.neighbours, d.weights, lambda, mu, d.dofs).A.rows == d.dofs.size);
}

namespace {
std::vector<std::string> messages;
void record(fmi3InstanceEnvironment, fmi3Status status, fmi3String, fmi3String message) {
  if (status == fmi3Error) messages.emplace_back(message);
}
}  // namespace

TEST_CASE("fmi3ExitInitializationMode returns fmi3Error with 'out of memory' when the assembly cannot allocate",
          "[fmi][memory]") {
  messages.clear();
  fmi3Instance s = fmi3InstantiateCoSimulation("oom", PERISTEP_INSTANTIATION_TOKEN, nullptr, fmi3False, fmi3True,
                                               fmi3False, fmi3False, nullptr, 0, nullptr, record, nullptr);
  REQUIRE(s != nullptr);
  const fmi3ValueReference vr[] = {PERISTEP_VR_NX, PERISTEP_VR_NY};
  const fmi3UInt64 n[] = {19, 19};  // a grid no other test builds: nothing cached
  REQUIRE(fmi3EnterConfigurationMode(s) == fmi3OK);
  REQUIRE(fmi3SetUInt64(s, vr, 2, n, 2) == fmi3OK);
  REQUIRE(fmi3ExitConfigurationMode(s) == fmi3OK);
  REQUIRE(fmi3EnterInitializationMode(s, fmi3False, 0, 0, fmi3False, 0) == fmi3OK);
  const long before = refused;
  {
    FailInParallel fail;
    CHECK(fmi3ExitInitializationMode(s) == fmi3Error);
  }
  CHECK(refused > before);
  REQUIRE(messages.size() == 1);
  CHECK(messages[0] == "fmi3ExitInitializationMode: out of memory");
  // The instance is Terminated (FMI 3.0 after fmi3Error) and can be reset and used again.
  REQUIRE(fmi3Reset(s) == fmi3OK);
  REQUIRE(fmi3EnterInitializationMode(s, fmi3False, 0, 0, fmi3False, 0) == fmi3OK);
  CHECK(fmi3ExitInitializationMode(s) == fmi3OK);
  fmi3FreeInstance(s);
}
