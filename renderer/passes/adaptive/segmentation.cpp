#include "passes/adaptive/segmentation.h"

#include <cstring>

#include "passes/storage_image.h"
#include "vk/context.h"

namespace taa {

namespace {

vk::SpecConstants specConstants(const spec::CaseSpec& spec, bool hasHistory) {
  const auto& a = spec.adaptive;
  vk::SpecConstants c;
  c.set(SEG_SPEC_HAS_HISTORY, hasHistory)
      .set(SEG_SPEC_TRACE_ALL, a.trace_all)
      .set(SEG_SPEC_FXAA, a.fxaa_out_of_history)
      .set(SEG_SPEC_TRACE_DISOCCLUDED, a.trace_disoccluded)
      .set(SEG_SPEC_DEBUG, spec.debug.output == spec::DebugOutput::Segmentation);
  return c;
}

std::vector<VkDescriptorType> segmentationBindings() {
  std::vector<VkDescriptorType> b(SEG_BINDING_COUNT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  b[SEG_BINDING_UNIFORMS] = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  b[SEG_BINDING_COUNTER] = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  b[SEG_BINDING_MASK] = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  b[SEG_BINDING_COUNTS] = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  b[SEG_BINDING_DEBUG] = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  return b;
}

}  // namespace

gpu::SegmentationUniforms makeSegmentationUniforms(const spec::CaseSpec& spec,
                                                   const script::FrameState& state) {
  const auto& a = spec.adaptive;
  gpu::SegmentationUniforms u{};
  u.weights = glm::vec4(a.weight_normal, a.weight_depth, a.weight_material, a.weight_luminance);
  u.params =
      glm::vec4(a.threshold, float(a.history_count), state.camera.nearPlane, state.camera.farPlane);
  const glm::vec2 size(state.renderSize);
  u.size = glm::vec4(size, 1.0f / size);
  return u;
}

SegmentationPass::SegmentationPass(vk::Context& ctx, const spec::CaseSpec& spec)
    : ctx_(ctx),
      spec_(spec),
      withHistory_(vk::createComputePipeline(ctx, "adaptive_segmentation.comp", segmentationBindings(), 0,
                                             specConstants(spec, true))),
      withoutHistory_(vk::createComputePipeline(ctx, "adaptive_segmentation.comp", segmentationBindings(),
                                                0, specConstants(spec, false))),
      uniforms_(ctx, sizeof(gpu::SegmentationUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
      counts_(ctx, sizeof(gpu::AdaptiveCounts), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  const glm::ivec2 size(spec.render.width, spec.render.height);
  mask_ = storageImage(ctx, "segmentation_mask", size, VK_FORMAT_R32_UINT);
  counter_ = storageImage(ctx, "trace_history_count", size, VK_FORMAT_R32_UINT);
  const bool debug = spec.debug.output == spec::DebugOutput::Segmentation;
  debug_ = storageImage(ctx, debug ? "segmentation_view" : "no_debug", debug ? size : glm::ivec2(1),
                        VK_FORMAT_R16G16B16A16_SFLOAT);
  if (!debug) noDebug_ = std::move(debug_);
}

gpu::AdaptiveCounts SegmentationPass::counts() const {
  gpu::AdaptiveCounts c;
  std::memcpy(&c, counts_.mapped(), sizeof(c));
  return c;
}

void SegmentationPass::record(VkCommandBuffer cmd, const script::FrameState& state,
                              const SegmentationInputs& in) {
  const gpu::SegmentationUniforms u = makeSegmentationUniforms(spec_, state);
  std::memcpy(uniforms_.mapped(), &u, sizeof(u));
  std::memset(counts_.mapped(), 0, sizeof(gpu::AdaptiveCounts));

  vk::Bindings b;
  b.uniform(SEG_BINDING_UNIFORMS, uniforms_.handle(), 0, sizeof(u));
  auto sampled = [&](uint32_t binding, vk::Image* image) {
    image->use(cmd, vk::Use::SampledCompute);
    b.sampled(binding, image->view(), point_.handle());
  };
  sampled(SEG_BINDING_COLOR, in.color);
  sampled(SEG_BINDING_DEPTH, in.depth);
  sampled(SEG_BINDING_NORMAL, in.normal);
  sampled(SEG_BINDING_IDS, in.ids);
  sampled(SEG_BINDING_REJECTION, in.rejection);
  sampled(SEG_BINDING_RESOLVED, in.resolved);
  // The counter is read and written in place, one pixel per invocation.
  counter_.use(cmd, vk::Use::StorageWrite);
  b.storage(SEG_BINDING_COUNTER, counter_.view());
  mask_.use(cmd, vk::Use::StorageWrite);
  b.storage(SEG_BINDING_MASK, mask_.view());
  b.storageBuffer(SEG_BINDING_COUNTS, counts_.handle(), 0, sizeof(gpu::AdaptiveCounts));
  vk::Image& debug = debug_ ? debug_ : noDebug_;
  debug.use(cmd, vk::Use::StorageWrite);
  b.storage(SEG_BINDING_DEBUG, debug.view());

  const vk::Pipeline& pipeline = state.resetHistory ? withoutHistory_ : withHistory_;
  pipeline.bind(cmd);
  b.push(ctx_, cmd, pipeline);
  vk::dispatch2d(cmd, uint32_t(state.renderSize.x), uint32_t(state.renderSize.y));
}

}  // namespace taa
