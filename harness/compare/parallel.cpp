#include "compare/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace taa::compare {

int resolveThreads(int requested, int items) {
  int n = requested > 0 ? requested : int(std::thread::hardware_concurrency());
  return std::clamp(n, 1, std::max(items, 1));
}

void parallelFor(int items, int threads, const std::function<void(int, int)>& fn) {
  const int workers = resolveThreads(threads, items);
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto work = [&](int worker) {
    for (int item = next++; item < items && !failed; item = next++) {
      try {
        fn(worker, item);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(errorMutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(size_t(workers - 1));
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0);  // the calling thread is worker 0
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace taa::compare
