// Move-only owners of buffers and images, each with its own allocation (the
// renderer holds a few dozen resources; a sub-allocator would buy nothing here).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <optional>
#include <string>

namespace taa::vk {

class Context;

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible);
  ~Buffer();
  Buffer(Buffer&& o) noexcept;
  Buffer& operator=(Buffer&& o) noexcept;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }  // host-visible buffers stay mapped
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// Where an image was last used; barriers are derived from the previous and next use.
enum class Use {
  Undefined,
  ColorAttachment,
  DepthAttachment,
  DepthResolve,     // written by a multisample depth resolve at the end of rendering
  SampledGraphics,  // read through a sampler in a fragment shader
  SampledCompute,   // read through a sampler (or texelFetch) in a compute shader
  StorageRead,      // imageLoad in a compute shader
  StorageWrite,     // imageStore in a compute shader
  TransferSrc,
  TransferDst,
};

struct ImageDesc {
  std::string name;  // shown in the run log and in validation messages
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t mipLevels = 1;
  uint32_t layers = 1;
  VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkImageUsageFlags usage = 0;
  uint32_t samples = 1;  // > 1: a multisampled attachment (one mip, resolved, never sampled)
};

class Image {
 public:
  Image() = default;
  Image(Context& ctx, const ImageDesc& desc);
  ~Image();
  Image(Image&& o) noexcept;
  Image& operator=(Image&& o) noexcept;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  const ImageDesc& desc() const { return desc_; }
  VkImageAspectFlags aspect() const;
  size_t bytes() const;  // of mip 0, all layers and samples
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

  // The barrier from the last use to `next` (all mips and layers); `next` becomes the
  // last use. None when the image is read again by the same use (same layout and stage,
  // so a later barrier's source still covers both reads).
  std::optional<VkImageMemoryBarrier2> transition(Use next);
  // Records transition(next) alone; a pass with several images batches them instead
  // (vk::BarrierBatch).
  void use(VkCommandBuffer cmd, Use next);
  Use lastUse() const { return use_; }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  ImageDesc desc_;
  Use use_ = Use::Undefined;
};

uint32_t formatBytes(VkFormat format);

}  // namespace taa::vk
