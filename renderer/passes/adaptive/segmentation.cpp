#include "passes/adaptive/segmentation.h"

#include <cstring>

#include "passes/storage_image.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

namespace {

vk::SpecConstants specConstants(const spec::CaseSpec& spec, bool hasHistory) {
  const auto& a = spec.adaptive;
  vk::SpecConstants c;
  c.set(SEG_SPEC_HAS_HISTORY, hasHistory)
      .set(SEG_SPEC_TRACE_ALL, a.trace_all)
      .set(SEG_SPEC_FXAA, a.fxaa_out_of_history)
      .set(SEG_SPEC_TRACE_DISOCCLUDED, a.trace_disoccluded)
      .set(SEG_SPEC_DEBUG, spec.debug.output == spec::DebugOutput::Segmentation)
      .set(SEG_SPEC_FXAA_BORDER, a.fxaa_debug_border);
  return c;
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
      withHistory_(
          vk::createComputePipeline(ctx, "adaptive_segmentation.comp", specConstants(spec, true))),
      withoutHistory_(
          vk::createComputePipeline(ctx, "adaptive_segmentation.comp", specConstants(spec, false))),
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

  const VkSampler point = point_.handle();
  vk::Dispatch(state.resetHistory ? withoutHistory_ : withHistory_)
      .uniform(SEG_BINDING_UNIFORMS, uniforms_.handle(), 0, sizeof(u))
      .sample(SEG_BINDING_COLOR, *in.color, point)
      .sample(SEG_BINDING_DEPTH, *in.depth, point)
      .sample(SEG_BINDING_NORMAL, *in.normal, point)
      .sample(SEG_BINDING_IDS, *in.ids, point)
      .sample(SEG_BINDING_REJECTION, *in.rejection, point)
      .sample(SEG_BINDING_RESOLVED, *in.resolved, point)
      // The counter is read and written in place, one pixel per invocation.
      .store(SEG_BINDING_COUNTER, counter_)
      .store(SEG_BINDING_MASK, mask_)
      .storageBuffer(SEG_BINDING_COUNTS, counts_.handle(), 0, sizeof(gpu::AdaptiveCounts))
      .store(SEG_BINDING_DEBUG, debug_ ? debug_ : noDebug_)
      .record(ctx_, cmd, uint32_t(state.renderSize.x), uint32_t(state.renderSize.y));
}

}  // namespace taa
