#include "passes/fxaa.h"

#include <cstdio>

namespace taa {

FxaaPass::FxaaPass(vk::Context& ctx, const FxaaSettings& s, bool masked)
    : settings_(s),
      masked_(masked),
      filter_(ctx, "fxaa.comp", glm::vec4(s.edgeThreshold, s.edgeThresholdMin, s.subpix, 0.0f),
              true, vk::SpecConstants().set(FXAA_SPEC_MASKED, masked)) {}

std::string FxaaPass::describe() const {
  char buf[192];
  std::snprintf(buf, sizeof(buf),
                "pass fxaa%s: 3.11 quality preset 39, edge threshold %g (min %g), subpix %g",
                masked_ ? " (out-of-history pixels only)" : "", double(settings_.edgeThreshold),
                double(settings_.edgeThresholdMin), double(settings_.subpix));
  return buf;
}

}  // namespace taa
