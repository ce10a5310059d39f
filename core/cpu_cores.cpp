#include "core/cpu_cores.h"

#include <sched.h>

#include <algorithm>
#include <thread>

namespace taa {

size_t availableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return size_t(std::max(1, CPU_COUNT(&set)));
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace taa
