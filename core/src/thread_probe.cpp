#include "thread_probe.hpp"

#include <condition_variable>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>
#include <vector>

namespace granpipe {

int startable_threads(int wanted) {
  std::mutex m;
  std::condition_variable released;
  bool release = false;
  std::vector<std::thread> started;
  started.reserve(static_cast<std::size_t>(wanted > 1 ? wanted - 1 : 0));
  try {
    // Each waits until all have started, so their stacks are held together, as a team's are.
    for (int k = 1; k < wanted; ++k) {
      started.emplace_back([&] {
        std::unique_lock lock(m);
        released.wait(lock, [&] { return release; });
      });
    }
  } catch (const std::system_error&) {
  } catch (const std::bad_alloc&) {
  }
  {
    const std::lock_guard lock(m);
    release = true;
  }
  released.notify_all();
  for (std::thread& t : started) t.join();
  return static_cast<int>(started.size()) + 1;
}

}  // namespace granpipe
