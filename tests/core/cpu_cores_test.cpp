// availableCores() is the CPU affinity's size (`taskset`, a container's cpuset), not the
// machine's: `run -j` defaults to it, so a job pinned to one core runs one worker.
#include "core/cpu_cores.h"

#include <gtest/gtest.h>
#include <sched.h>

namespace taa::cpu_cores_test {
namespace {

TEST(AvailableCores, FollowTheAffinityOfTheCallingThread) {
  cpu_set_t saved;
  CPU_ZERO(&saved);
  ASSERT_EQ(sched_getaffinity(0, sizeof(saved), &saved), 0);
  EXPECT_EQ(availableCores(), size_t(CPU_COUNT(&saved)));
  // Pinned to the first core it may use (this thread only; restored below).
  int first = 0;
  while (!CPU_ISSET(first, &saved)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  const size_t pinned = availableCores();
  ASSERT_EQ(sched_setaffinity(0, sizeof(saved), &saved), 0);
  EXPECT_EQ(pinned, 1u);
}

}  // namespace
}  // namespace taa::cpu_cores_test
