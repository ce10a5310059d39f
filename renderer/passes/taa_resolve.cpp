#include "passes/taa_resolve.h"

#include <cstring>
#include <glm/matrix.hpp>

#include "passes/storage_image.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

namespace {

using namespace spec;

vk::Image dummy(vk::Context& ctx, VkFormat format, vk::Use use = vk::Use::SampledCompute) {
  vk::ImageDesc d;
  d.name = "dummy";
  d.format = format;
  d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  vk::Image image(ctx, d);
  // Cleared so that a stray read would see zeros, never undefined memory.
  VkCommandBuffer cmd = ctx.beginCommands();
  image.use(cmd, vk::Use::TransferDst);
  VkClearColorValue zero{};
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
  image.use(cmd, use);
  ctx.submitAndWait(cmd);
  return image;
}

// One eye: the resolve never runs in stereo (TSCMAA replaces it there).
glm::ivec2 resolveOutputSize(const CaseSpec& s) { return {s.render.width, s.render.height}; }

}  // namespace

vk::SpecConstants taaSpecConstants(const CaseSpec& spec, bool hasHistory) {
  // Accumulation is the full resolve with per-tap geometric consistency as its only
  // history validation and no colour rectification, filter or dynamic alpha.
  TaaSpec t = spec.taa;
  if (t.mode == TaaMode::Accumulate) {
    t.consistency = true;
    t.depth_culling = t.anti_ghosting = false;
    t.rectify = Rectify::None;
    t.variance_clip = t.shaped_neighborhood = t.shrink_chroma = false;
    t.luma_weight = t.velocity_alpha = t.reduce_blend_near_clamp = t.velocity_in_alpha = false;
    t.tonemap_weighting = ToneWeight::None;
  }
  const int mode = t.mode == TaaMode::PassThrough ? 0 : t.mode == TaaMode::Basic ? 1 : 2;
  const bool full = mode == 2;
  const bool upsample = spec.render.upsample != 1.0f || !spec.render.scale_schedule.empty();
  vk::SpecConstants c;
  c.set(TAA_SPEC_MODE, mode)
      .set(TAA_SPEC_HAS_HISTORY, hasHistory)
      .set(TAA_SPEC_TONE_WEIGHT, mode != 0 ? int(t.tonemap_weighting) : 0)
      .set(TAA_SPEC_USE_VELOCITY, full ? int(t.use_velocity) : 0)
      .set(TAA_SPEC_VELOCITY_SAMPLING, full ? int(t.velocity_sampling) : 0)
      .set(TAA_SPEC_HISTORY_FILTER, full ? int(t.history_filter) : 0)
      .set(TAA_SPEC_REJECT_OFFSCREEN, full && t.reject_offscreen)
      .set(TAA_SPEC_DEPTH_CULLING, full && t.depth_culling)
      .set(TAA_SPEC_CONSISTENCY, full && t.consistency)
      .set(TAA_SPEC_ANTI_GHOSTING, full && t.anti_ghosting)
      .set(TAA_SPEC_RECTIFY, full ? int(t.rectify) : 0)
      .set(TAA_SPEC_VARIANCE_CLIP, full && t.variance_clip)
      .set(TAA_SPEC_SHAPED, full && t.shaped_neighborhood)
      .set(TAA_SPEC_YCOCG, full && t.color_space == ColorSpace::YCoCg)
      .set(TAA_SPEC_SHRINK_CHROMA, full && t.shrink_chroma)
      .set(TAA_SPEC_LUMA_WEIGHT, full && t.luma_weight)
      .set(TAA_SPEC_VELOCITY_ALPHA, full && t.velocity_alpha)
      .set(TAA_SPEC_REDUCE_BLEND, full && t.reduce_blend_near_clamp)
      .set(TAA_SPEC_VELOCITY_IN_ALPHA, full && t.velocity_in_alpha)
      .set(TAA_SPEC_UPSAMPLE, upsample)
      .set(TAA_SPEC_DEBUG, int(spec.debug.output))
      .set(TAA_SPEC_REJECT_MASK, spec.taa.mode == TaaMode::Adaptive)
      .set(TAA_SPEC_HALF_HISTORY, t.history_format == HistoryFormat::Rgba16f);
  return c;
}

gpu::TaaUniforms makeTaaUniforms(const CaseSpec& spec, const script::FrameState& s, glm::ivec2 prevRenderSize) {
  const auto& t = spec.taa;
  gpu::TaaUniforms u{};
  u.invViewProj = glm::inverse(s.camera.viewProjection);
  u.prevViewProj = s.prevCamera.viewProjection;
  const glm::vec2 render(s.renderSize), prev(prevRenderSize), out(resolveOutputSize(spec));
  u.renderSize = glm::vec4(render, 1.0f / render);
  u.prevRenderSize = glm::vec4(prev, 1.0f / prev);
  u.outputSize = glm::vec4(out, 1.0f / out);
  u.jitter = glm::vec4(s.jitter, 0.0f, 0.0f);
  u.blend = glm::vec4(t.alpha, t.rejection_alpha, t.alpha_min, t.alpha_max);
  u.limits = glm::vec4(t.variance_gamma, t.depth_threshold, t.velocity_alpha_px, spec.debug.scale);
  u.planes = glm::vec4(s.camera.nearPlane, s.camera.farPlane, t.consistency_depth, t.consistency_normal);
  return u;
}

TaaResolvePass::TaaResolvePass(vk::Context& ctx, const CaseSpec& spec, const PassPlan& plan)
    : ctx_(ctx), spec_(spec), dummyFloat_(dummy(ctx, VK_FORMAT_R16G16B16A16_SFLOAT)),
      dummyUint_(dummy(ctx, VK_FORMAT_R32_UINT)),
      dummyStorage_(dummy(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, vk::Use::StorageWrite)),
      dummyReject_(dummy(ctx, VK_FORMAT_R32_UINT, vk::Use::StorageWrite)),
      uniforms_(ctx, sizeof(gpu::TaaUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
      linear_(ctx, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  withHistory_ = vk::createComputePipeline(ctx, "taa_resolve.comp", taaSpecConstants(spec, true));
  withoutHistory_ =
      vk::createComputePipeline(ctx, "taa_resolve.comp", taaSpecConstants(spec, false));
  const VkFormat format = spec.taa.history_format == HistoryFormat::Rgba32f ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                                           : VK_FORMAT_R16G16B16A16_SFLOAT;
  history_[0] = storageImage(ctx, "history_a", resolveOutputSize(spec), format);
  history_[1] = storageImage(ctx, "history_b", resolveOutputSize(spec), format);
  // The segmentation view is drawn by the adaptive pass, not here.
  if (plan.debugView && spec.debug.output != DebugOutput::Segmentation)
    debug_ = storageImage(ctx, "debug_view", resolveOutputSize(spec), VK_FORMAT_R16G16B16A16_SFLOAT);
  if (plan.adaptive) rejection_ = storageImage(ctx, "rejection", resolveOutputSize(spec), VK_FORMAT_R32_UINT);
}

std::string TaaResolvePass::describe() const {
  return "taa_resolve spec constants: " + taaSpecConstants(spec_, true).describe();
}

void TaaResolvePass::record(VkCommandBuffer cmd, const script::FrameState& state, const TaaInputs& in) {
  const glm::ivec2 prevSize = state.frame == 0 ? state.renderSize : prevRenderSize_;
  const gpu::TaaUniforms u = makeTaaUniforms(spec_, state, prevSize);
  std::memcpy(uniforms_.mapped(), &u, sizeof(u));
  prevRenderSize_ = state.renderSize;

  vk::Image& previous = history_[current_];
  current_ ^= 1;
  vk::Image& next = history_[current_];
  const bool hasHistory = !state.resetHistory;

  vk::Dispatch d(hasHistory ? withHistory_ : withoutHistory_);
  d.uniform(TAA_BINDING_UNIFORMS, uniforms_.handle(), 0, sizeof(gpu::TaaUniforms));
  auto sample = [&](uint32_t binding, vk::Image* image, vk::Image& fallback, VkSampler sampler) {
    d.sample(binding, image ? *image : fallback, sampler);
  };
  sample(TAA_BINDING_COLOR, in.color, dummyFloat_, point_.handle());
  sample(TAA_BINDING_DEPTH, in.depth, dummyFloat_, point_.handle());
  sample(TAA_BINDING_VELOCITY, in.velocity, dummyFloat_, point_.handle());
  sample(TAA_BINDING_IDS, in.ids, dummyUint_, point_.handle());
  sample(TAA_BINDING_NORMAL, in.normal, dummyFloat_, point_.handle());
  sample(TAA_BINDING_HISTORY, &previous, dummyFloat_, linear_.handle());
  sample(TAA_BINDING_PREV_DEPTH, in.prevDepth, dummyFloat_, point_.handle());
  sample(TAA_BINDING_PREV_NORMAL, in.prevNormal, dummyFloat_, point_.handle());
  sample(TAA_BINDING_PREV_IDS, in.prevIds, dummyUint_, point_.handle());
  sample(TAA_BINDING_PREV_VELOCITY, in.prevVelocity, dummyFloat_, point_.handle());
  d.store(TAA_BINDING_HISTORY_OUT, next)
      .store(TAA_BINDING_DEBUG_OUT, debug_ ? debug_ : dummyStorage_)
      .store(TAA_BINDING_REJECT_OUT, rejection_ ? rejection_ : dummyReject_)
      .record(ctx_, cmd, uint32_t(spec_.render.width), uint32_t(spec_.render.height));
}

}  // namespace taa
