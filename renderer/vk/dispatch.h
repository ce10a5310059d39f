// One compute dispatch as a pass states it: the images it samples, loads and stores at
// which bindings, its buffers and push constants. Recording it transitions every image
// at one barrier (vk::BarrierBatch), pushes the descriptors (checked against the layout
// reflected from the shader), pushes the constants and dispatches workgroups of the
// shader's own size. A pass never writes a barrier, a layout or a group count by hand.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "vk/barrier.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa::vk {

class Dispatch {
 public:
  explicit Dispatch(const Pipeline& pipeline) : pipeline_(pipeline) {}

  // Read through a sampler (or texelFetch).
  Dispatch& sample(uint32_t binding, Image& image, VkSampler sampler);
  // A sampled image without a sampler (HLSL's Texture2D), and a sampler on its own.
  Dispatch& texture(uint32_t binding, Image& image);
  Dispatch& sampler(uint32_t binding, VkSampler sampler);
  // imageLoad only.
  Dispatch& load(uint32_t binding, Image& image);
  // imageStore (loads of the same image allowed: read-modify-write in place).
  Dispatch& store(uint32_t binding, Image& image);
  // Every element of a sampled array whose images stay in their sampled state (textures).
  Dispatch& sampledArray(uint32_t binding, const std::vector<VkImageView>& views,
                         const std::vector<VkSampler>& samplers);
  Dispatch& uniform(uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range);
  Dispatch& storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                          VkDeviceSize range = VK_WHOLE_SIZE);
  // A buffer dependency to wait for at this dispatch's barrier.
  Dispatch& after(VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);
  template <class T>
  Dispatch& constants(const T& block) {
    constants_.resize(sizeof(T));
    std::memcpy(constants_.data(), &block, sizeof(T));
    return *this;
  }

  // Barrier, bind, descriptors, constants, then groups covering width x height x depth.
  void record(const Context& ctx, VkCommandBuffer cmd, uint32_t width, uint32_t height,
              uint32_t depth = 1);
  // The same with the group counts read from `args` at `offset` (VkDispatchIndirectCommand).
  void recordIndirect(const Context& ctx, VkCommandBuffer cmd, VkBuffer args, VkDeviceSize offset);

 private:
  void prepare(const Context& ctx, VkCommandBuffer cmd);
  const Pipeline& pipeline_;
  BarrierBatch barriers_;
  Bindings bindings_;
  std::vector<uint8_t> constants_;
};

}  // namespace taa::vk
