#include "passes/tscmaa_support.h"

#include <algorithm>
#include <glm/matrix.hpp>

#include "vk/barrier.h"
#include "vk/context.h"

namespace taa::tscmaa {

vk::Image image(vk::Context& ctx, const std::string& name, glm::ivec2 size, VkFormat format,
                VkImageUsageFlags usage) {
  vk::ImageDesc d;
  d.name = name;
  d.width = uint32_t(size.x);
  d.height = uint32_t(size.y);
  d.format = format;
  d.usage = usage;
  return vk::Image(ctx, d);
}

std::string describeImage(const vk::Image& image) {
  return "buffer " + image.desc().name + " " + std::to_string(image.desc().width) + "x" +
         std::to_string(image.desc().height) + " (" + std::to_string(image.bytes() / 1024) +
         " KiB)";
}

vk::Buffer listBuffer(vk::Context& ctx, uint32_t pixels) {
  const VkDeviceSize bytes = sizeof(gpu::EdgeListHeader) + VkDeviceSize(pixels) * sizeof(uint32_t);
  return vk::Buffer(ctx, bytes,
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                        VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                    false);
}

VkDeviceSize uniformStride(vk::Context& ctx) {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(ctx.physical(), &props);
  const VkDeviceSize align = props.limits.minUniformBufferOffsetAlignment;
  const VkDeviceSize largest = std::max(sizeof(gpu::TaaUniforms), sizeof(gpu::TscmaaUniforms));
  return (largest + align - 1) / align * align;
}

// Each pipeline's layout is its shader's own: a binding a step does not use is not declared.
vk::Pipeline edgePipeline(vk::Context& ctx) {
  return vk::createComputePipeline(ctx, "tscmaa_edges.comp");
}

vk::Pipeline cmaaPipeline(vk::Context& ctx) {
  return vk::createComputePipeline(ctx, "tscmaa_cmaa.comp");
}

vk::Pipeline taaPipeline(vk::Context& ctx) {
  return vk::createComputePipeline(ctx, "tscmaa_taa.comp");
}

gpu::TaaUniforms taaUniforms(const script::FrameState& s, glm::ivec2 eyeSize, float historyWeight) {
  gpu::TaaUniforms u{};
  u.invViewProj = glm::inverse(s.camera.viewProjection);
  u.prevViewProj = s.prevCamera.viewProjection;
  const glm::vec4 size(glm::vec2(eyeSize), 1.0f / glm::vec2(eyeSize));
  u.renderSize = u.prevRenderSize = u.outputSize = size;
  u.jitter = glm::vec4(s.jitter, 0.0f, 0.0f);
  u.view = glm::vec4(s.camera.nearPlane, s.camera.farPlane, 1.0f, 0.0f);
  // tscmaa_taa.comp reads alpha and the variance gamma; its other settings are fixed there.
  u.settings[spec::TAA_PARAM_ALPHA / 4][spec::TAA_PARAM_ALPHA % 4] = 1.0f - historyWeight;
  u.settings[spec::TAA_PARAM_VARIANCE_GAMMA / 4][spec::TAA_PARAM_VARIANCE_GAMMA % 4] = 1.0f;
  return u;
}

void copyRegion(VkCommandBuffer cmd, vk::Image& from, glm::ivec2 fromOffset, vk::Image& to,
                glm::ivec2 toOffset, glm::ivec2 size) {
  vk::BarrierBatch().use(from, vk::Use::TransferSrc).use(to, vk::Use::TransferDst).flush(cmd);
  VkImageCopy region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffset = {fromOffset.x, fromOffset.y, 0};
  region.dstOffset = {toOffset.x, toOffset.y, 0};
  region.extent = {uint32_t(size.x), uint32_t(size.y), 1};
  vkCmdCopyImage(cmd, from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

}  // namespace taa::tscmaa
