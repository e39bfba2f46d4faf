#pragma once
// An exception must not leave an OpenMP region: the runtime calls std::terminate and the importer dies
// (a std::bad_alloc in the assembly did). Each thread runs its share through capture(), which keeps the
// first exception and makes the other threads skip their remaining work; rethrow() after the region
// hands it to the caller, and so to the FMI layer's catch (fmi3Error plus one message).
#include <atomic>
#include <exception>
#include <mutex>

namespace peristep {

class ParallelErrors {
 public:
  template <class Body>
  void capture(Body&& body) noexcept {
    if (failed_.load(std::memory_order_relaxed)) return;
    try {
      body();
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
};

}  // namespace peristep
