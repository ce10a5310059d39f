// The comparison code's parallel loop (compare/parallel.h): the thread count asked for, within
// 1 and the number of items, and every item exactly once whatever the count.
#include "compare/parallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace taa::parallel_test {

TEST(ParallelFor, TheThreadCountIsTheRequestWithinOneAndTheItems) {
  EXPECT_EQ(compare::resolveThreads(3, 10), 3);
  EXPECT_EQ(compare::resolveThreads(8, 2), 2);
  EXPECT_EQ(compare::resolveThreads(4, 0), 1);
  EXPECT_EQ(compare::resolveThreads(-2, 10), std::min(10, std::max(1, int(std::thread::hardware_concurrency()))));
}

TEST(ParallelFor, EveryItemOnceOnTheWorkersAskedFor) {
  std::vector<std::atomic<int>> seen(64);
  std::mutex m;
  std::set<int> workers;
  compare::parallelFor(64, 3, [&](int worker, int item) {
    ++seen[size_t(item)];
    const std::lock_guard<std::mutex> lock(m);
    workers.insert(worker);
  });
  for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i].load(), 1) << "item " << i;
  for (int w : workers) EXPECT_TRUE(w >= 0 && w < 3) << w;
  EXPECT_THROW(compare::parallelFor(8, 2, [](int, int item) {
                 if (item == 5) throw std::runtime_error("item 5");
               }),
               std::runtime_error);
}

}  // namespace taa::parallel_test
