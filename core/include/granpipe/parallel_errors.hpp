#pragma once
// An exception thrown inside an OpenMP region ends the process (std::terminate: "terminate
// called after throwing an instance of 'std::bad_alloc'", exit 134, the run's folder marked
// running). Each region's body runs under one of these, and the first exception is thrown
// again after the region, on the thread that called it, where the run reports it.
#include <exception>
#include <mutex>

namespace granpipe {

class ParallelErrors {
 public:
  // Runs body(); an exception it throws is kept (the first one only) instead of leaving.
  template <class Body>
  void run(Body&& body) noexcept {
    try {
      body();
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!first_) first_ = std::current_exception();
    }
  }
  // Throws the first exception kept, if any. Call after the region.
  void rethrow() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr first_;
};

}  // namespace granpipe
