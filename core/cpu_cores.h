// The cores this process may run on: `run -j`'s default worker count, and what lavapipe's
// rasteriser threads are shared out of when several devices render at once.
#pragma once

#include <cstddef>

namespace taa {

// The CPU affinity's size, at least 1.
size_t availableCores();

}  // namespace taa
