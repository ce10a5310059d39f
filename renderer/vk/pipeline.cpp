#include "vk/pipeline.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "core/input_file.h"
#include "core/sha256.h"
#include "scene/scene.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/pipeline_cache.h"

namespace taa::vk {

SpecConstants& SpecConstants::set(uint32_t id, uint32_t value) {
  entries_.push_back({id, uint32_t(data_.size() * 4), 4});
  data_.push_back(value);
  return *this;
}

SpecConstants& SpecConstants::setFloat(uint32_t id, float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  return set(id, bits);
}

std::optional<uint32_t> SpecConstants::value(uint32_t id) const {
  for (size_t i = 0; i < entries_.size(); ++i)
    if (entries_[i].constantID == id) return data_[i];
  return std::nullopt;
}

std::string SpecConstants::describe() const {
  std::string out;
  for (size_t i = 0; i < entries_.size(); ++i)
    out += (i ? " " : "") + std::to_string(entries_[i].constantID) + "=" + std::to_string(data_[i]);
  return out;
}

std::string SpecConstants::bytes() const {
  std::string out;
  for (size_t i = 0; i < entries_.size(); ++i) {
    out.append(reinterpret_cast<const char*>(&entries_[i].constantID), 4);
    out.append(reinterpret_cast<const char*>(&data_[i]), 4);
  }
  return out;
}

VkSpecializationInfo SpecConstants::info() const {
  return {uint32_t(entries_.size()), entries_.data(), data_.size() * 4, data_.data()};
}

PipelineObjects::~PipelineObjects() {
  if (!device) return;
  vkDestroyPipeline(device, pipeline, nullptr);
  vkDestroyPipelineLayout(device, layout, nullptr);
  vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
}

void Pipeline::pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const {
  if (bytes > o_->interface.pushConstantBytes)
    throw std::logic_error(o_->name + ": " + std::to_string(bytes) +
                           " bytes of push constants, but its shaders declare " +
                           std::to_string(o_->interface.pushConstantBytes));
  vkCmdPushConstants(cmd, o_->layout, o_->interface.stages, 0, bytes, data);
}

void Pipeline::dispatch(VkCommandBuffer cmd, uint32_t width, uint32_t height,
                        uint32_t depth) const {
  const auto& l = o_->interface.localSize;
  vkCmdDispatch(cmd, (width + l[0] - 1) / l[0], (height + l[1] - 1) / l[1],
                (depth + l[2] - 1) / l[2]);
}

std::string shaderDir() {
  if (const char* env = std::getenv("TAA_SHADER_DIR"); env && *env) return env;
  // An installed harness finds its SPIR-V beside it (PREFIX/bin -> PREFIX/share), so it
  // works after the build tree is gone; a binary in the build tree falls through to the
  // build's shader folder.
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / TAA_SHADER_INSTALL_SUBDIR;
    if (std::filesystem::is_directory(installed, ec)) return installed.string();
  }
  return TAA_SHADER_DIR;
}

namespace {
// Per thread: a worker renders one case at a time on its own thread.
thread_local std::set<std::string>* tShaderUse = nullptr;
}  // namespace

std::set<std::string>* setShaderUseSet(std::set<std::string>* names) {
  std::set<std::string>* previous = tShaderUse;
  tShaderUse = names;
  return previous;
}

std::vector<uint32_t> readSpirvFile(const std::string& path) {
  const std::string fix = "build the project (ninja -C build) or set TAA_SHADER_DIR";
  std::string bytes;
  try {
    bytes = readInputFile(path, kMaxBuiltSpirvBytes);
  } catch (const InputFileMissing&) {
    throw EnvironmentError("shader " + path + " not found; " + fix);
  } catch (const InputFileError& e) {
    throw EnvironmentError("shader " + path + " " + refusalProblem(e, path) + "; " + fix);
  }
  if (bytes.empty() || bytes.size() % 4 != 0)
    throw EnvironmentError("shader " + path + " is " + std::to_string(bytes.size()) +
                           " bytes, not whole 32-bit SPIR-V words; " + fix);
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

std::vector<uint32_t> loadSpirv(const std::string& name) {
  if (tShaderUse) tShaderUse->insert(name);
  return readSpirvFile(shaderDir() + "/" + name + ".spv");
}

namespace {

VkShaderModule createModule(VkDevice device, const std::vector<uint32_t>& words) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = words.size() * 4;
  info.pCode = words.data();
  VkShaderModule module;
  VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
  return module;
}

// The set-0 layout and pipeline layout of `shader`'s interface: every declared binding at
// the stages that declare it, one push-constant range for all stages of the pipeline.
void createLayouts(VkDevice device, const ShaderInterface& shader, const std::string& name,
                   VkDescriptorSetLayout& setLayout, VkPipelineLayout& layout) {
  std::vector<VkDescriptorSetLayoutBinding> b;
  for (const auto& r : shader.bindings) {
    if (r.set != 0)
      throw ShaderInterfaceError(name + " declares descriptor set " + std::to_string(r.set) +
                               "; pipelines push one set, set 0");
    b.push_back({r.binding, r.type, r.count, r.stages, nullptr});
  }
  VkDescriptorSetLayoutCreateInfo set{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  set.bindingCount = uint32_t(b.size());
  set.pBindings = b.data();
  VK_CHECK(vkCreateDescriptorSetLayout(device, &set, nullptr, &setLayout));
  VkPushConstantRange range{shader.stages, 0, shader.pushConstantBytes};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = 1;
  info.pSetLayouts = &setLayout;
  info.pushConstantRangeCount = shader.pushConstantBytes ? 1 : 0;
  info.pPushConstantRanges = &range;
  VK_CHECK(vkCreatePipelineLayout(device, &info, nullptr, &layout));
}

// A specialized workgroup size (local_size_x_id) takes the value the pipeline gives it.
void specializeLocalSize(ShaderInterface& shader, const SpecConstants& spec) {
  for (size_t k = 0; k < 3; ++k)
    if (shader.localSizeSpecId[k] >= 0)
      if (const auto v = spec.value(uint32_t(shader.localSizeSpecId[k]))) shader.localSize[k] = *v;
}

}  // namespace

Pipeline createComputePipeline(Context& ctx, const std::string& shader, const SpecConstants& spec) {
  return createComputePipelineFromSpirv(ctx, shader, loadSpirv(shader), spec);
}

Pipeline createComputePipelineFromSpirv(Context& ctx, const std::string& shader,
                                        const std::vector<uint32_t>& words,
                                        const SpecConstants& spec) {
  const std::string key = "compute\n" + shader + "\n" + sha256Hex(words.data(), words.size() * 4) +
                          "\n" + spec.bytes();
  return Pipeline(ctx.pipelines().get(key, [&] {
    auto o = std::make_shared<PipelineObjects>();
    o->device = ctx.device();
    o->name = shader;
    o->bindPoint = VK_PIPELINE_BIND_POINT_COMPUTE;
    o->interface = reflectSpirv(words, shader);
    if (o->interface.stages != VK_SHADER_STAGE_COMPUTE_BIT)
      throw ShaderInterfaceError(shader + " is not a compute shader");
    specializeLocalSize(o->interface, spec);
    createLayouts(o->device, o->interface, shader, o->setLayout, o->layout);
    VkShaderModule module = createModule(o->device, words);
    const VkSpecializationInfo specInfo = spec.info();
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = o->interface.entryPoint.c_str();  // a user's HLSL names its own
    info.stage.pSpecializationInfo = &specInfo;
    info.layout = o->layout;
    const VkResult r =
        vkCreateComputePipelines(o->device, VK_NULL_HANDLE, 1, &info, nullptr, &o->pipeline);
    vkDestroyShaderModule(o->device, module, nullptr);
    VK_CHECK(r);
    return std::shared_ptr<const PipelineObjects>(std::move(o));
  }));
}

namespace {

std::shared_ptr<const PipelineObjects> makeGraphicsPipeline(Context& ctx, const std::string& name,
                                                            const GraphicsDesc& d,
                                                            const std::vector<uint32_t>& vertWords,
                                                            const std::vector<uint32_t>& fragWords) {
  auto o = std::make_shared<PipelineObjects>();
  VkDevice device = o->device = ctx.device();
  o->name = name;
  o->bindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  o->interface = mergeInterfaces(reflectSpirv(vertWords, d.vertexShader),
                                 reflectSpirv(fragWords, d.fragmentShader), name);
  createLayouts(device, o->interface, name, o->setLayout, o->layout);
  VkShaderModule vert = createModule(device, vertWords);
  VkShaderModule frag = createModule(device, fragWords);
  const VkSpecializationInfo specInfo = d.spec.info();
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert;
  stages[0].pName = "main";
  stages[0].pSpecializationInfo = &specInfo;
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag;
  stages[1].pName = "main";
  stages[1].pSpecializationInfo = &specInfo;

  VkVertexInputBindingDescription binding{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription attributes[5] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
      {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv)},
      {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, color)},
      {4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv1)}};
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  if (d.vertexInput) {
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 5;
    vertexInput.pVertexAttributeDescriptions = attributes;
  }
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = d.cullMode;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VkSampleCountFlagBits(d.samples);
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = d.depthTest;
  depth.depthWriteEnable = d.depthWrite;
  depth.depthCompareOp = d.depthCompare;

  std::vector<VkPipelineColorBlendAttachmentState> blends(d.colorFormats.size());
  for (size_t i = 0; i < blends.size(); ++i) {
    auto& b = blends[i];
    // An attachment without a target writes nothing; saying so keeps the validation layer from
    // expecting the shader (which does not declare that output) to write it.
    b.colorWriteMask = d.colorFormats[i] == VK_FORMAT_UNDEFINED
                           ? 0
                           : VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                                 VK_COLOR_COMPONENT_A_BIT;
    if (d.blendFirstAttachment) {
      if (i == 0) {
        b.blendEnable = VK_TRUE;
        b.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        b.colorBlendOp = VK_BLEND_OP_ADD;
        b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        b.alphaBlendOp = VK_BLEND_OP_ADD;
      } else {
        b.colorWriteMask = 0;  // blended surfaces leave the G-buffer's other targets alone
      }
    }
  }
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = uint32_t(blends.size());
  blend.pAttachments = blends.data();
  const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                          VK_DYNAMIC_STATE_CULL_MODE, VK_DYNAMIC_STATE_FRONT_FACE};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = d.dynamicFaces ? 4 : 2;
  dynamic.pDynamicStates = dynamicStates;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = uint32_t(d.colorFormats.size());
  rendering.pColorAttachmentFormats = d.colorFormats.data();
  rendering.depthAttachmentFormat = d.depthFormat;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = o->layout;
  const VkResult r =
      vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &o->pipeline);
  vkDestroyShaderModule(device, vert, nullptr);
  vkDestroyShaderModule(device, frag, nullptr);
  VK_CHECK(r);
  return o;
}

}  // namespace

// A new GraphicsDesc field changes the size: add it to the key below, then update the size.
// A field left out would let two different pipelines share one cache entry.
static_assert(sizeof(GraphicsDesc) == 168, "GraphicsDesc changed: key every field in graphicsPipelineKey");

std::string graphicsPipelineKey(const std::string& name, const GraphicsDesc& d,
                                const std::vector<uint32_t>& vertWords,
                                const std::vector<uint32_t>& fragWords) {
  std::string key = "graphics\n" + name + "\n" + d.vertexShader + "\n" +
                    sha256Hex(vertWords.data(), vertWords.size() * 4) + "\n" + d.fragmentShader +
                    "\n" + sha256Hex(fragWords.data(), fragWords.size() * 4) + "\n" +
                    d.spec.bytes() + "\n";
  auto add = [&key](uint64_t v) { key.append(reinterpret_cast<const char*>(&v), sizeof(v)); };
  add(d.colorFormats.size());
  for (const VkFormat f : d.colorFormats) add(uint64_t(f));
  add(d.vertexInput);
  add(uint64_t(d.depthFormat));
  add(d.depthTest);
  add(d.depthWrite);
  add(uint64_t(d.depthCompare));
  add(d.cullMode);
  add(d.blendFirstAttachment);
  add(d.samples);
  return key;
}

Pipeline createGraphicsPipeline(Context& ctx, const std::string& name, const GraphicsDesc& d) {
  const auto vertWords = loadSpirv(d.vertexShader);
  const auto fragWords = loadSpirv(d.fragmentShader);
  return Pipeline(ctx.pipelines().get(graphicsPipelineKey(name, d, vertWords, fragWords), [&] {
    return makeGraphicsPipeline(ctx, name, d, vertWords, fragWords);
  }));
}

Bindings& Bindings::add(uint32_t binding, VkDescriptorType type, const VkDescriptorImageInfo* image,
                        const VkDescriptorBufferInfo* buffer) {
  VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  w.dstBinding = binding;
  w.descriptorCount = 1;
  w.descriptorType = type;
  w.pImageInfo = image;
  w.pBufferInfo = buffer;
  writes_.push_back(w);
  return *this;
}

Bindings& Bindings::sampled(uint32_t binding, VkImageView view, VkSampler sampler) {
  images_.push_back({sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  return add(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, &images_.back(), nullptr);
}

Bindings& Bindings::texture(uint32_t binding, VkImageView view) {
  images_.push_back({VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  return add(binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, &images_.back(), nullptr);
}

Bindings& Bindings::sampler(uint32_t binding, VkSampler sampler) {
  images_.push_back({sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED});
  return add(binding, VK_DESCRIPTOR_TYPE_SAMPLER, &images_.back(), nullptr);
}

Bindings& Bindings::storage(uint32_t binding, VkImageView view) {
  images_.push_back({VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL});
  return add(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, &images_.back(), nullptr);
}

Bindings& Bindings::uniform(uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
  buffers_.push_back({buffer, offset, range});
  return add(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, nullptr, &buffers_.back());
}

Bindings& Bindings::storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
  buffers_.push_back({buffer, offset, range});
  return add(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, nullptr, &buffers_.back());
}

Bindings& Bindings::sampledArray(uint32_t binding, const std::vector<VkImageView>& views,
                                 const std::vector<VkSampler>& samplers) {
  if (views.empty() || views.size() != samplers.size())
    throw std::logic_error("Bindings::sampledArray: need one sampler per view, and at least one");
  // pImageInfo must point at consecutive elements: a deque keeps them only per chunk.
  arrays_.emplace_back();
  for (size_t i = 0; i < views.size(); ++i)
    arrays_.back().push_back({samplers[i], views[i], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  w.dstBinding = binding;
  w.descriptorCount = uint32_t(views.size());
  w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  w.pImageInfo = arrays_.back().data();
  writes_.push_back(w);
  return *this;
}

void Bindings::push(const Context& ctx, VkCommandBuffer cmd, const Pipeline& pipeline) const {
  for (const auto& w : writes_) {
    const ReflectedBinding* b = pipeline.interface().find(0, w.dstBinding);
    if (!b || b->type != w.descriptorType || w.descriptorCount > b->count)
      throw std::logic_error(
          pipeline.name() + ": binding " + std::to_string(w.dstBinding) + " is given a " +
          descriptorTypeName(w.descriptorType) + " (" + std::to_string(w.descriptorCount) +
          "), but its shaders declare " +
          (b ? descriptorTypeName(b->type) + std::string(" (") + std::to_string(b->count) + ")"
             : std::string("nothing there")));
  }
  ctx.pushDescriptorSet(cmd, pipeline.bindPoint(), pipeline.layout(), 0, uint32_t(writes_.size()), writes_.data());
}

Sampler::Sampler(Context& ctx, VkFilter filter, VkSamplerAddressMode address, float maxLod, bool mipLinear)
    : device_(ctx.device()) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = mipLinear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = address;
  info.maxLod = maxLod;
  VK_CHECK(vkCreateSampler(device_, &info, nullptr, &sampler_));
}

Sampler::Sampler(Context& ctx, const VkSamplerCreateInfo& info) : device_(ctx.device()) {
  VK_CHECK(vkCreateSampler(device_, &info, nullptr, &sampler_));
}

Sampler::~Sampler() {
  if (device_) vkDestroySampler(device_, sampler_, nullptr);
}
Sampler::Sampler(Sampler&& o) noexcept { *this = std::move(o); }
Sampler& Sampler::operator=(Sampler&& o) noexcept {
  if (this != &o) {
    if (device_) vkDestroySampler(device_, sampler_, nullptr);
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    sampler_ = std::exchange(o.sampler_, VK_NULL_HANDLE);
  }
  return *this;
}

}  // namespace taa::vk
