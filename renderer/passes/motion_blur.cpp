#include "passes/motion_blur.h"

#include <cstdio>
#include <stdexcept>

#include "common/shared.h"
#include "passes/post_filter.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

MotionBlurPass::MotionBlurPass(vk::Context& ctx, const MotionBlurSettings& s)
    : ctx_(ctx),
      settings_(s),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  // One tap would divide by zero in the tap spacing; the case range starts at 2.
  if (s.samples < 2) throw std::invalid_argument("motion blur needs at least 2 samples");
  vk::SpecConstants spec;
  spec.set(MB_SPEC_SAMPLES, s.samples).set(MB_SPEC_VELOCITY_IN_ALPHA, s.velocityInAlpha);
  pipeline_ = vk::createComputePipeline(ctx, "motion_blur.comp", spec);
}

void MotionBlurPass::record(VkCommandBuffer cmd, vk::Image& color, vk::Image& velocity,
                            vk::Image& depth, vk::Image& output, glm::ivec2 size) {
  for (const vk::Image* image : {&color, &velocity, &depth, &output})
    requireCovers(*image, size, "motion_blur");
  vk::Dispatch(pipeline_)
      .sample(MB_BINDING_COLOR, color, point_.handle())
      .sample(MB_BINDING_VELOCITY, velocity, point_.handle())
      .sample(MB_BINDING_DEPTH, depth, point_.handle())
      .store(MB_BINDING_OUT, output)
      .constants(
          makePostPush(size, glm::vec4(settings_.scale, settings_.depthTolerance, 0.0f, 0.0f)))
      .record(ctx_, cmd, uint32_t(size.x), uint32_t(size.y));
}

void MotionBlurPass::record(const FrameView& f, vk::Image& input, vk::Image& output) {
  record(f.cmd, input, f.targets->velocity, f.targets->depth, output, f.state->renderSize);
}

std::string MotionBlurPass::describe() const {
  char buf[160];
  std::snprintf(buf, sizeof(buf),
                "pass motion_blur: %d taps, scale %g, depth-aware (tolerance %g), alpha = %s",
                settings_.samples, double(settings_.scale), double(settings_.depthTolerance),
                settings_.velocityInAlpha ? "speed in render pixels" : "1");
  return buf;
}

}  // namespace taa
