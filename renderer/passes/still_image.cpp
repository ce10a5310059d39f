#include "passes/still_image.h"

#include <vector>

#include "common/shared.h"
#include "vk/dispatch.h"
#include "vk/transfer.h"

namespace taa {

StillImagePass::StillImagePass(vk::Context& ctx, const Image& image)
    : ctx_(ctx),
      pipeline_(vk::createComputePipeline(ctx, "still_image.comp")),
      linear_(ctx, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE),
      nearest_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  // RGBA32F: the samples as read, gray or RGB widened (alpha is not used).
  std::vector<float> rgba(image.pixelCount() * 4, 1.0f);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4 + size_t(c)] =
            image.at(x, y, image.channels >= 3 ? c : 0);
  vk::ImageDesc d;
  d.name = "still_image";
  d.width = uint32_t(image.width);
  d.height = uint32_t(image.height);
  d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
  d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  image_ = vk::Image(ctx, d);
  vk::uploadImage(ctx, image_, {rgba.data()});
}

void StillImagePass::record(VkCommandBuffer cmd, vk::Image& color, glm::ivec2 size,
                            glm::vec2 jitter, bool nearest) {
  gpu::StillPush push{};
  push.size = glm::vec4(float(size.x), float(size.y), 1.0f / float(size.x), 1.0f / float(size.y));
  push.jitter = glm::vec4(jitter, 0.0f, 0.0f);
  vk::Dispatch(pipeline_)
      .sample(STILL_BINDING_IMAGE, image_, nearest ? nearest_.handle() : linear_.handle())
      .store(STILL_BINDING_OUT, color)
      .constants(push)
      .record(ctx_, cmd, uint32_t(size.x), uint32_t(size.y));
}

}  // namespace taa
