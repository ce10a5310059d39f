#include "passes/inject.h"

#include <algorithm>

#include "common/shared.h"

namespace taa {

InjectPass::InjectPass(vk::Context& ctx, const spec::CaseSpec& spec)
    : ctx_(ctx), spec_(spec),
      pipeline_(vk::createComputePipeline(ctx, "inject.comp", {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                          sizeof(gpu::InjectPush))) {}

bool InjectPass::appliesTo(int frame) const {
  const auto& f = spec_.inject.frames;
  return std::find(f.begin(), f.end(), frame) != f.end();
}

void InjectPass::record(VkCommandBuffer cmd, vk::Image& color) {
  gpu::InjectPush push{};
  const auto& pixels = spec_.inject.pixels;
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
  push.params = glm::vec4(float(pixels.size()), float(int(spec_.inject.value)), 0.0f, 0.0f);
  color.use(cmd, vk::Use::StorageWrite);
  pipeline_.bind(cmd);
  vk::Bindings().storage(0, color.view()).push(ctx_, cmd, pipeline_);
  vkCmdPushConstants(cmd, pipeline_.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  vkCmdDispatch(cmd, 1, 1, 1);
}

}  // namespace taa
