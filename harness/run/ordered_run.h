// Items of a batch worked on by several threads, finished in item order: the caller sees
// item 0, then 1, ... whatever order the workers finish them in, so everything written from
// `deliver` (console lines, results) is the same for any worker count.
#pragma once

#include <cstddef>
#include <functional>

namespace taa::run {

// Runs work(worker, item) for items 0..count-1 on `workers` threads (worker in [0, workers);
// a worker takes the lowest item no one has taken), and deliver(item) on the calling thread
// in item order, each as soon as it and every item before it are done. When deliver returns
// false, no later item is started or delivered (those already running finish and are
// dropped), so a stop depends on the items alone, not on which finished first. An exception
// from work(item) is rethrown when item's turn to be delivered comes; one from deliver at
// once; either after every worker has stopped. workers <= 1 runs everything on the calling
// thread.
void runOrdered(size_t count, size_t workers,
                const std::function<void(size_t worker, size_t item)>& work,
                const std::function<bool(size_t item)>& deliver);

}  // namespace taa::run
