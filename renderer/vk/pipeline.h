// Pipelines with one push-descriptor set each: a pass binds by pushing its
// descriptors, so no pools or set lifetimes exist anywhere. Technique switches are
// specialization constants, so disabled code is removed when the driver compiles.
// Descriptor layouts, push-constant ranges and workgroup sizes come from the shaders'
// SPIR-V (vk/spirv_reflect.h): a pass names its shader, never its binding types.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "vk/spirv_reflect.h"

namespace taa::vk {

class Context;

class SpecConstants {
 public:
  SpecConstants& set(uint32_t id, uint32_t value);
  SpecConstants& set(uint32_t id, int32_t value) { return set(id, static_cast<uint32_t>(value)); }
  SpecConstants& set(uint32_t id, bool value) { return set(id, value ? 1u : 0u); }
  SpecConstants& setFloat(uint32_t id, float value);
  // The value given for `id`, if any (a specialized workgroup size reads it).
  std::optional<uint32_t> value(uint32_t id) const;
  // Human-readable "id=value" list, for the run log.
  std::string describe() const;
  VkSpecializationInfo info() const;
  // Every (id, value) pair as bytes, in the order set: part of a pipeline's cache key.
  std::string bytes() const;

 private:
  std::vector<VkSpecializationMapEntry> entries_;
  std::vector<uint32_t> data_;
};

// The Vulkan objects of one pipeline; destroyed with the last Pipeline (or cache entry)
// that holds them.
struct PipelineObjects {
  PipelineObjects() = default;
  PipelineObjects(const PipelineObjects&) = delete;
  PipelineObjects& operator=(const PipelineObjects&) = delete;
  ~PipelineObjects();
  VkDevice device = VK_NULL_HANDLE;
  std::string name;
  VkPipelineBindPoint bindPoint = VK_PIPELINE_BIND_POINT_COMPUTE;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  ShaderInterface interface;
};

// A pipeline is immutable once made, so passes of several renderers on one context share it:
// createComputePipeline and createGraphicsPipeline hand out the context's cached one
// (vk/pipeline_cache.h) when its inputs are the same.
class Pipeline {
 public:
  Pipeline() = default;
  explicit Pipeline(std::shared_ptr<const PipelineObjects> objects) : o_(std::move(objects)) {}

  VkPipeline handle() const { return o_ ? o_->pipeline : VK_NULL_HANDLE; }
  VkPipelineLayout layout() const { return o_->layout; }
  VkPipelineBindPoint bindPoint() const { return o_->bindPoint; }
  const std::string& name() const { return o_->name; }
  // What the shaders declare; localSize already holds any specialized workgroup size.
  const ShaderInterface& interface() const { return o_->interface; }
  void bind(VkCommandBuffer cmd) const { vkCmdBindPipeline(cmd, o_->bindPoint, o_->pipeline); }
  // Pushes `bytes` at offset 0 to every stage of the push-constant range; throws
  // std::logic_error when the shaders' block is smaller.
  void pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const;
  // Enough workgroups of the shader's local size to cover width x height x depth.
  void dispatch(VkCommandBuffer cmd, uint32_t width, uint32_t height, uint32_t depth = 1) const;
  explicit operator bool() const { return handle() != VK_NULL_HANDLE; }

 private:
  std::shared_ptr<const PipelineObjects> o_;
};

// Where SPIR-V is read from: $TAA_SHADER_DIR, else PREFIX/share/taa-harness/shaders beside an
// installed binary, else the build's shader folder.
std::string shaderDir();

// Largest SPIR-V file the shader folder may hold (the largest, the resolve with line info, is
// 0.2 MB).
inline constexpr uint64_t kMaxBuiltSpirvBytes = uint64_t(64) << 20;

// The words of a SPIR-V file of the shader folder, read through the hardened reader (a FIFO
// there cannot hang the harness). Throws EnvironmentError naming the file and the fix.
std::vector<uint32_t> readSpirvFile(const std::string& path);

// SPIR-V compiled at build time, found by file name (e.g. "taa_resolve.comp") in shaderDir().
// The name goes into this thread's shader-use set, if one is installed.
std::vector<uint32_t> loadSpirv(const std::string& name);

// Installs `names` as this thread's shader-use set (nullptr: none); returns the previous one.
std::set<std::string>* setShaderUseSet(std::set<std::string>* names);

// The set layout, push-constant range and workgroup size are the shader's own (set 0 only:
// a second set is an error naming the shader).
Pipeline createComputePipeline(Context& ctx, const std::string& shader,
                               const SpecConstants& spec = {});
// The same from SPIR-V in memory (a user's shader compiled at run time); `name` is for messages.
Pipeline createComputePipelineFromSpirv(Context& ctx, const std::string& name,
                                        const std::vector<uint32_t>& words,
                                        const SpecConstants& spec = {});

struct GraphicsDesc {
  std::string vertexShader;
  std::string fragmentShader;
  SpecConstants spec;                      // applied to both stages
  bool vertexInput = true;                 // scene::Vertex layout; false: positions from gl_VertexIndex
  std::vector<VkFormat> colorFormats;      // VK_FORMAT_UNDEFINED: the shader's output is discarded
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  bool depthTest = true;
  bool depthWrite = true;
  VkCompareOp depthCompare = VK_COMPARE_OP_GREATER;  // reversed Z
  VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
  // Cull mode and front face set per draw (vkCmdSetCullMode / vkCmdSetFrontFace, core in
  // Vulkan 1.3) instead of cullMode: single- and double-sided materials, mirrored instances.
  bool dynamicFaces = false;
  bool blendFirstAttachment = false;       // premultiplied-free "over" blending on attachment 0
  uint32_t samples = 1;                    // rasterization samples, the attachments' count
};

Pipeline createGraphicsPipeline(Context& ctx, const std::string& name, const GraphicsDesc& desc);
// What the context's pipeline cache knows a graphics pipeline by: its name, both stages' SPIR-V,
// and every field of `desc` (a field added to GraphicsDesc must be added here; a static_assert
// on the struct's size says so).
std::string graphicsPipelineKey(const std::string& name, const GraphicsDesc& desc,
                                const std::vector<uint32_t>& vertWords,
                                const std::vector<uint32_t>& fragWords);

// Descriptor writes for one push: collect, then push before a draw or dispatch.
class Bindings {
 public:
  Bindings& sampled(uint32_t binding, VkImageView view, VkSampler sampler);
  // Every element of an array binding, in order.
  Bindings& sampledArray(uint32_t binding, const std::vector<VkImageView>& views,
                         const std::vector<VkSampler>& samplers);
  Bindings& texture(uint32_t binding, VkImageView view);  // a sampled image, no sampler
  Bindings& sampler(uint32_t binding, VkSampler sampler);
  Bindings& storage(uint32_t binding, VkImageView view);
  Bindings& uniform(uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range);
  Bindings& storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range);
  // Throws std::logic_error naming the pipeline when a write's binding is not in its
  // shaders' layout or has another descriptor type or count.
  void push(const Context& ctx, VkCommandBuffer cmd, const Pipeline& pipeline) const;

 private:
  Bindings& add(uint32_t binding, VkDescriptorType type, const VkDescriptorImageInfo* image,
                const VkDescriptorBufferInfo* buffer);
  std::vector<VkWriteDescriptorSet> writes_;
  std::deque<VkDescriptorImageInfo> images_;  // deque: stable addresses for pImageInfo
  std::deque<VkDescriptorBufferInfo> buffers_;
  std::deque<std::vector<VkDescriptorImageInfo>> arrays_;
};

class Sampler {
 public:
  Sampler() = default;
  Sampler(Context& ctx, VkFilter filter, VkSamplerAddressMode address, float maxLod = 0.0f, bool mipLinear = false);
  // Any other sampler (e.g. a depth-comparison sampler for shadow maps).
  Sampler(Context& ctx, const VkSamplerCreateInfo& info);
  ~Sampler();
  Sampler(Sampler&& o) noexcept;
  Sampler& operator=(Sampler&& o) noexcept;
  VkSampler handle() const { return sampler_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace taa::vk
