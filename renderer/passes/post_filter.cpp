#include "passes/post_filter.h"

#include <stdexcept>

#include "passes/storage_image.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

vk::Image makePostImage(vk::Context& ctx, const std::string& name, glm::ivec2 size) {
  vk::ImageDesc d;
  d.name = name;
  d.width = uint32_t(size.x);
  d.height = uint32_t(size.y);
  d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  d.usage =
      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  return vk::Image(ctx, d);
}

gpu::PostPush makePostPush(glm::ivec2 size, glm::vec4 params) {
  gpu::PostPush push{};
  push.size = glm::vec4(glm::vec2(size), 1.0f / glm::vec2(size));
  push.params = params;
  return push;
}

void requireCovers(const vk::Image& image, glm::ivec2 size, const char* pass) {
  if (size.x < 1 || size.y < 1 || uint32_t(size.x) > image.desc().width ||
      uint32_t(size.y) > image.desc().height)
    throw std::logic_error(std::string(pass) + ": region " + std::to_string(size.x) + "x" +
                           std::to_string(size.y) + " does not fit image '" + image.desc().name +
                           "'");
}

PostFilter::PostFilter(vk::Context& ctx, const std::string& shader, glm::vec4 params,
                       bool maskBinding, const vk::SpecConstants& spec)
    : ctx_(ctx),
      name_(shader),
      params_(params),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  pipeline_ = vk::createComputePipeline(ctx, shader, spec);
  if (maskBinding != (pipeline_.interface().find(0, POST_BINDING_MASK) != nullptr))
    throw std::logic_error(shader + (maskBinding ? " declares no" : " declares a") +
                           " mask binding, unlike what its pass says");
  if (maskBinding) {
    vk::ImageDesc d;
    d.name = "no_mask";
    d.format = VK_FORMAT_R32_UINT;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    noMask_ = zeroedImage(ctx, d, vk::Use::SampledCompute);
  }
}

void PostFilter::record(VkCommandBuffer cmd, vk::Image& input, vk::Image& output, glm::ivec2 size,
                        vk::Image* mask) {
  requireCovers(input, size, name_.c_str());
  requireCovers(output, size, name_.c_str());
  if (&input == &output) throw std::logic_error(name_ + ": input and output must differ");
  vk::Dispatch d(pipeline_);
  d.sample(POST_BINDING_INPUT, input, point_.handle()).store(POST_BINDING_OUTPUT, output);
  if (noMask_)
    d.sample(POST_BINDING_MASK, mask ? *mask : noMask_, point_.handle());
  else if (mask)
    throw std::logic_error(name_ + ": a mask was given, but the filter has no mask binding");
  d.constants(makePostPush(size, params_)).record(ctx_, cmd, uint32_t(size.x), uint32_t(size.y));
}

}  // namespace taa
