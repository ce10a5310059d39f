// runOrdered (run/ordered_run.h): whatever the worker count, items are delivered in order, a
// stop from deliver starts nothing later, and an item's failure is rethrown at its turn, its
// delivery never made.
#include "run/ordered_run.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace taa::ordered_run_test {

TEST(OrderedRun, DeliversInItemOrderForAnyWorkerCount) {
  for (size_t workers : {1u, 2u, 3u, 8u}) {
    std::vector<size_t> delivered;
    std::atomic<size_t> worked{0};
    run::runOrdered(
        20, workers, [&](size_t, size_t) { ++worked; },
        [&](size_t k) {
          delivered.push_back(k);
          return true;
        });
    EXPECT_EQ(worked, 20u) << workers;
    ASSERT_EQ(delivered.size(), 20u) << workers;
    for (size_t k = 0; k < delivered.size(); ++k) EXPECT_EQ(delivered[k], k) << workers;
  }
}

TEST(OrderedRun, AFailedItemIsRethrownAtItsTurnAndNeverDelivered) {
  for (size_t workers : {1u, 2u, 3u}) {
    std::vector<size_t> delivered;
    try {
      run::runOrdered(
          6, workers,
          [&](size_t, size_t k) {
            if (k == 2) throw std::runtime_error("item 2 failed");
          },
          [&](size_t k) {
            delivered.push_back(k);
            return true;
          });
      ADD_FAILURE() << workers << " workers: the failure was not rethrown";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "item 2 failed") << workers;
    }
    EXPECT_EQ(delivered, (std::vector<size_t>{0, 1})) << workers << " workers";
  }
}

TEST(OrderedRun, AStopFromDeliverDeliversNothingLater) {
  for (size_t workers : {1u, 2u, 4u}) {
    std::vector<size_t> delivered;
    run::runOrdered(
        10, workers, [](size_t, size_t) {},
        [&](size_t k) {
          delivered.push_back(k);
          return k < 3;
        });
    EXPECT_EQ(delivered, (std::vector<size_t>{0, 1, 2, 3})) << workers << " workers";
  }
}

}  // namespace taa::ordered_run_test
