#include "passes/adaptive/adaptive.h"

#include <cstdio>

#include "vk/barrier.h"
#include "vk/context.h"

namespace taa {

namespace {

vk::Image outputImage(vk::Context& ctx, const char* name, const spec::CaseSpec& spec,
                      VkImageUsageFlags usage) {
  vk::ImageDesc d;
  d.name = name;
  d.width = uint32_t(spec.render.width);
  d.height = uint32_t(spec.render.height);
  d.format = spec.taa.history_format == spec::HistoryFormat::Rgba32f
                 ? VK_FORMAT_R32G32B32A32_SFLOAT
                 : VK_FORMAT_R16G16B16A16_SFLOAT;
  d.usage = usage | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  return vk::Image(ctx, d);
}

// The counts are written by a shader and read through mapped memory after the wait.
void hostReadBarrier(VkCommandBuffer cmd) {
  vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void copyImage(VkCommandBuffer cmd, vk::Image& from, vk::Image& to) {
  vk::BarrierBatch().use(from, vk::Use::TransferSrc).use(to, vk::Use::TransferDst).flush(cmd);
  VkImageCopy region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstSubresource = region.srcSubresource;
  region.extent = {to.desc().width, to.desc().height, 1};
  vkCmdCopyImage(cmd, from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

}  // namespace

AdaptivePass::AdaptivePass(vk::Context& ctx, const spec::CaseSpec& spec, const GpuScene& scene,
                           const DrawList& firstFrame, CaptureSet captures)
    : spec_(spec), segmentation_(ctx, spec), trace_(ctx, spec, scene, firstFrame) {
  if (spec.adaptive.fxaa_out_of_history && !spec.adaptive.trace_all) {
    fxaa_ = std::make_unique<FxaaPass>(ctx, FxaaSettings{}, true);
    filtered_ = outputImage(ctx, "adaptive_fxaa", spec, VK_IMAGE_USAGE_STORAGE_BIT);
  }
  if (captures.has(Capture::Resolved))
    beforeTrace_ = outputImage(ctx, "taa_resolve_copy", spec, VK_IMAGE_USAGE_TRANSFER_DST_BIT);
}

vk::Image& AdaptivePass::record(VkCommandBuffer cmd, vk::GpuTimer& timer,
                                const AdaptiveFrame& frame, const SegmentationInputs& in,
                                vk::Image& resolved) {
  const script::FrameState& state = *frame.state;
  lastSize_ = state.renderSize;
  if (beforeTrace_) copyImage(cmd, resolved, beforeTrace_);
  timer.begin(cmd, "adaptive_segmentation");
  SegmentationInputs withResolved = in;
  withResolved.resolved = &resolved;
  segmentation_.record(cmd, state, withResolved);
  timer.end(cmd);
  timer.begin(cmd, "adaptive_trace");
  trace_.record(cmd, state, *frame.draws, frame.frameUniforms, frame.lodBias, segmentation_.mask(),
                resolved);
  timer.end(cmd);
  hostReadBarrier(cmd);
  if (!fxaa_) return resolved;
  timer.begin(cmd, "adaptive_fxaa");
  fxaa_->record(cmd, resolved, filtered_, state.renderSize, &segmentation_.mask());
  timer.end(cmd);
  return filtered_;
}

vk::Image& AdaptivePass::record(const FrameView& f, ResolveStage& resolve, vk::Image& resolveInput,
                                vk::Image& resolved) {
  GBufferTargets& t = *f.targets;
  const SegmentationInputs seg{&resolveInput,       &t.depth, &t.normal, &t.ids,
                               resolve.rejection(), nullptr};
  const AdaptiveFrame frame{f.state, f.draws, f.frameUniforms, f.lodBias};
  return record(f.cmd, *f.timer, frame, seg, resolved);
}

std::vector<std::pair<std::string, double>> AdaptivePass::stats() const {
  const gpu::AdaptiveCounts c = segmentation_.counts();
  const double pixels = double(lastSize_.x) * double(lastSize_.y);
  if (pixels <= 0.0) return {};
  return {{"traced_share", double(c.traced) / pixels}, {"fxaa_share", double(c.fxaa) / pixels}};
}

std::vector<StageCapture> AdaptivePass::captures() {
  // At the frame's render size, which is the resolve's output size (no upsampling here).
  std::vector<StageCapture> out = {{Capture::Segmentation, &segmentation_.mask(), lastSize_}};
  if (beforeTrace_) out.push_back({Capture::Resolved, &beforeTrace_, lastSize_});
  return out;
}

std::vector<std::string> AdaptivePass::describe() const {
  const auto& a = spec_.adaptive;
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "pass adaptive_segmentation: threshold %g, weights normal %g depth %g material %g "
                "luminance %g, "
                "history count %d%s%s",
                double(a.threshold), double(a.weight_normal), double(a.weight_depth),
                double(a.weight_material), double(a.weight_luminance), a.history_count,
                a.trace_disoccluded ? ", disocclusions traced" : "",
                a.trace_all ? ", every pixel traced" : "");
  std::vector<std::string> out = {buf, trace_.describe()};
  if (fxaa_) out.push_back(fxaa_->describe());
  return out;
}

}  // namespace taa
