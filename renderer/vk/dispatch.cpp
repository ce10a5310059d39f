#include "vk/dispatch.h"

namespace taa::vk {

Dispatch& Dispatch::sample(uint32_t binding, Image& image, VkSampler sampler) {
  barriers_.use(image, Use::SampledCompute);
  bindings_.sampled(binding, image.view(), sampler);
  return *this;
}

Dispatch& Dispatch::texture(uint32_t binding, Image& image) {
  barriers_.use(image, Use::SampledCompute);
  bindings_.texture(binding, image.view());
  return *this;
}

Dispatch& Dispatch::sampler(uint32_t binding, VkSampler sampler) {
  bindings_.sampler(binding, sampler);
  return *this;
}

Dispatch& Dispatch::load(uint32_t binding, Image& image) {
  barriers_.use(image, Use::StorageRead);
  bindings_.storage(binding, image.view());
  return *this;
}

Dispatch& Dispatch::store(uint32_t binding, Image& image) {
  barriers_.use(image, Use::StorageWrite);
  bindings_.storage(binding, image.view());
  return *this;
}

Dispatch& Dispatch::sampledArray(uint32_t binding, const std::vector<VkImageView>& views,
                                 const std::vector<VkSampler>& samplers) {
  bindings_.sampledArray(binding, views, samplers);
  return *this;
}

Dispatch& Dispatch::uniform(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                            VkDeviceSize range) {
  bindings_.uniform(binding, buffer, offset, range);
  return *this;
}

Dispatch& Dispatch::storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                  VkDeviceSize range) {
  bindings_.storageBuffer(binding, buffer, offset, range);
  return *this;
}

Dispatch& Dispatch::after(VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                          VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
  barriers_.memory(srcStage, srcAccess, dstStage, dstAccess);
  return *this;
}

void Dispatch::prepare(const Context& ctx, VkCommandBuffer cmd) {
  barriers_.flush(cmd);
  pipeline_.bind(cmd);
  bindings_.push(ctx, cmd, pipeline_);
  if (!constants_.empty())
    pipeline_.pushConstants(cmd, constants_.data(), uint32_t(constants_.size()));
}

void Dispatch::record(const Context& ctx, VkCommandBuffer cmd, uint32_t width, uint32_t height,
                      uint32_t depth) {
  prepare(ctx, cmd);
  pipeline_.dispatch(cmd, width, height, depth);
}

void Dispatch::recordIndirect(const Context& ctx, VkCommandBuffer cmd, VkBuffer args,
                              VkDeviceSize offset) {
  prepare(ctx, cmd);
  vkCmdDispatchIndirect(cmd, args, offset);
}

}  // namespace taa::vk
