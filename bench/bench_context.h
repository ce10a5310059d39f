// The benchmarks' one Vulkan context (lavapipe unless TAA_DEVICE names another), with
// Mesa's shader cache in a temporary folder of its own.
#pragma once

#include "vk/context.h"

namespace taa::bench {

vk::Context& context();

}  // namespace taa::bench
