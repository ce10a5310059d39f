#include "passes/cas.h"

#include <algorithm>
#include <cstdio>

namespace taa {

float casPeak(float sharpness) {
  const float s = std::clamp(sharpness, 0.0f, 1.0f);
  return -1.0f / (8.0f + (5.0f - 8.0f) * s);
}

CasPass::CasPass(vk::Context& ctx, float sharpness)
    : sharpness_(sharpness),
      filter_(ctx, "cas.comp", glm::vec4(casPeak(sharpness), 0.0f, 0.0f, 0.0f)) {}

std::string CasPass::describe() const {
  char buf[128];
  std::snprintf(buf, sizeof(buf), "pass cas: sharpness %g, lobe peak -1/%g, tonemapped c/(1+c)",
                double(sharpness_), double(-1.0f / casPeak(sharpness_)));
  return buf;
}

}  // namespace taa
