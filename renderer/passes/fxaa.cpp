#include "passes/fxaa.h"

#include <cstdio>

namespace taa {

FxaaPass::FxaaPass(vk::Context& ctx, const FxaaSettings& s)
    : settings_(s),
      filter_(ctx, "fxaa.comp", glm::vec4(s.edgeThreshold, s.edgeThresholdMin, s.subpix, 0.0f)) {}

std::string FxaaPass::describe() const {
  char buf[128];
  std::snprintf(buf, sizeof(buf),
                "pass fxaa: 3.11 quality preset 39, edge threshold %g (min %g), subpix %g",
                double(settings_.edgeThreshold), double(settings_.edgeThresholdMin),
                double(settings_.subpix));
  return buf;
}

}  // namespace taa
