#include "passes/inject.h"

#include <algorithm>
#include <stdexcept>

#include "common/shared.h"
#include "vk/dispatch.h"

namespace taa {

InjectPass::InjectPass(vk::Context& ctx, const spec::CaseSpec& spec)
    : ctx_(ctx), spec_(spec), pipeline_(vk::createComputePipeline(ctx, "inject.comp")) {}

bool InjectPass::appliesTo(int frame) const {
  const auto& f = spec_.inject.frames;
  return std::find(f.begin(), f.end(), frame) != f.end();
}

namespace {
float injectShaderValue(spec::InjectValue v) {
  switch (v) {
    case spec::InjectValue::Nan: return INJECT_NAN;
    case spec::InjectValue::PosInf: return INJECT_POS_INF;
    case spec::InjectValue::NegInf: return INJECT_NEG_INF;
  }
  throw std::logic_error("inject: an InjectValue without a shader name");
}
}  // namespace

gpu::InjectPush makeInjectPush(const spec::InjectSpec& inject) {
  gpu::InjectPush push{};
  const auto& pixels = inject.pixels;
  for (size_t i = 0; i < pixels.size(); ++i) {
    glm::vec4& pair = push.pixels[i / 2];
    if (i % 2 == 0) {
      pair.x = pixels[i].x;
      pair.y = pixels[i].y;
    } else {
      pair.z = pixels[i].x;
      pair.w = pixels[i].y;
    }
  }
  push.params = glm::vec4(float(pixels.size()), injectShaderValue(inject.value), 0.0f, 0.0f);
  return push;
}

void InjectPass::record(VkCommandBuffer cmd, vk::Image& color) {
  const gpu::InjectPush push = makeInjectPush(spec_.inject);
  const auto& pixels = spec_.inject.pixels;
  // One invocation per listed pixel (at least one group, as the shader checks the count).
  const auto invocations = uint32_t(std::max<size_t>(pixels.size(), 1));
  vk::Dispatch(pipeline_).store(0, color).constants(push).record(ctx_, cmd, invocations, 1);
}

}  // namespace taa
