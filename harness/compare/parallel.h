// A minimal parallel loop for the comparison code: work items are claimed in order from a shared
// counter by a fixed set of threads. Callers make every item's result independent of which
// thread ran it and when, so results never depend on the thread count.
#pragma once

#include <functional>

namespace taa::compare {

// The thread count a request of `requested` means: 0 is one per hardware thread; never more than
// `items`, never less than 1.
int resolveThreads(int requested, int items);

// Calls fn(worker, item) for every item in [0, items), on resolveThreads(threads, items) threads;
// `worker` in [0, that count) lets a caller keep scratch memory per thread. The first exception
// thrown by any call is rethrown here once all threads have stopped.
void parallelFor(int items, int threads, const std::function<void(int worker, int item)>& fn);

}  // namespace taa::compare
