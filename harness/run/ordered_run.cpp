#include "run/ordered_run.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace taa::run {

void runOrdered(size_t count, size_t workers,
                const std::function<void(size_t, size_t)>& work,
                const std::function<bool(size_t)>& deliver) {
  workers = std::min(workers, count);
  if (workers <= 1) {
    for (size_t k = 0; k < count; ++k) {
      work(0, k);
      if (!deliver(k)) return;
    }
    return;
  }
  std::mutex mutex;
  std::condition_variable finished;
  std::vector<char> done(count, 0);
  std::vector<std::exception_ptr> errors(count);
  size_t next = 0;      // the lowest item not taken yet
  size_t end = count;   // items from here on are not started
  auto worker = [&](size_t w) {
    for (;;) {
      size_t k;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= end) return;
        k = next++;
      }
      std::exception_ptr error;
      try {
        work(w, k);
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mutex);
      errors[k] = error;
      done[k] = 1;
      finished.notify_all();
    }
  };
  std::vector<std::thread> threads;
  for (size_t w = 0; w < workers; ++w) threads.emplace_back(worker, w);
  auto stopAndJoin = [&](size_t stopAt) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      end = std::min(end, stopAt);
    }
    for (auto& t : threads) t.join();
  };
  std::exception_ptr failure;
  for (size_t k = 0; k < count && !failure; ++k) {
    {
      std::unique_lock<std::mutex> lock(mutex);
      finished.wait(lock, [&] { return done[k] != 0; });
      failure = errors[k];
    }
    if (failure) break;
    bool more = false;
    try {
      more = deliver(k);
    } catch (...) {
      failure = std::current_exception();
      break;
    }
    if (!more) {
      stopAndJoin(k + 1);
      return;
    }
  }
  stopAndJoin(failure ? 0 : count);
  if (failure) std::rethrow_exception(failure);
}

}  // namespace taa::run
