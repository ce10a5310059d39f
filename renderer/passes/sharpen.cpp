#include "passes/sharpen.h"

#include <cstdio>

namespace taa {

SharpenPass::SharpenPass(vk::Context& ctx, float amount)
    : amount_(amount), filter_(ctx, "sharpen.comp", glm::vec4(amount, 0.0f, 0.0f, 0.0f)) {}

std::string SharpenPass::describe() const {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "pass sharpen: 5-tap gradient, amount %g", double(amount_));
  return buf;
}

}  // namespace taa
