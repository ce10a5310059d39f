#include "passes/motion_blur.h"

#include <cstdio>
#include <stdexcept>

#include "common/shared.h"
#include "passes/post_filter.h"
#include "vk/context.h"

namespace taa {

MotionBlurPass::MotionBlurPass(vk::Context& ctx, const MotionBlurSettings& s)
    : ctx_(ctx),
      settings_(s),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  // One tap would divide by zero in the tap spacing; the case range starts at 2.
  if (s.samples < 2) throw std::invalid_argument("motion blur needs at least 2 samples");
  std::vector<VkDescriptorType> bindings(MB_BINDING_COUNT,
                                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  bindings[MB_BINDING_OUT] = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  vk::SpecConstants spec;
  spec.set(MB_SPEC_SAMPLES, s.samples).set(MB_SPEC_VELOCITY_IN_ALPHA, s.velocityInAlpha);
  pipeline_ =
      vk::createComputePipeline(ctx, "motion_blur.comp", bindings, sizeof(gpu::PostPush), spec);
}

void MotionBlurPass::record(VkCommandBuffer cmd, vk::Image& color, vk::Image& velocity,
                            vk::Image& depth, vk::Image& output, glm::ivec2 size) {
  for (const vk::Image* image : {&color, &velocity, &depth, &output})
    requireCovers(*image, size, "motion_blur");
  color.use(cmd, vk::Use::SampledCompute);
  velocity.use(cmd, vk::Use::SampledCompute);
  depth.use(cmd, vk::Use::SampledCompute);
  output.use(cmd, vk::Use::StorageWrite);
  pipeline_.bind(cmd);
  vk::Bindings()
      .sampled(MB_BINDING_COLOR, color.view(), point_.handle())
      .sampled(MB_BINDING_VELOCITY, velocity.view(), point_.handle())
      .sampled(MB_BINDING_DEPTH, depth.view(), point_.handle())
      .storage(MB_BINDING_OUT, output.view())
      .push(ctx_, cmd, pipeline_);
  const gpu::PostPush push =
      makePostPush(size, glm::vec4(settings_.scale, settings_.depthTolerance, 0.0f, 0.0f));
  vkCmdPushConstants(cmd, pipeline_.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  vk::dispatch2d(cmd, uint32_t(size.x), uint32_t(size.y));
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
