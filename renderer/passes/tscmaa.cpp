#include "passes/tscmaa.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/matrix.hpp>
#include <stdexcept>

#include "passes/tscmaa_support.h"
#include "script/stereo.h"
#include "vk/barrier.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

using tscmaa::copyRegion;

struct TscmaaPass::Eye {
  int index = 0;
  glm::ivec2 offset{0};  // of its half in the side-by-side images
  vk::Buffer edgeList, taaList;
  vk::Image history[2];
  bool hasHistory = false;
  VkDeviceSize uniformOffset = 0, taaUniformOffset = 0;
};

gpu::TscmaaUniforms makeTscmaaUniforms(const spec::TscmaaSpec& t, glm::ivec2 eyeSize, int eye) {
  gpu::TscmaaUniforms u{};
  u.params = glm::vec4(t.edge_threshold, t.non_dominant_edge_removal, t.blurriness, t.taa_share);
  u.size = glm::vec4(glm::vec2(eyeSize), 1.0f / glm::vec2(eyeSize));
  // 65536 * share, so share 1 selects every 16-bit hash and share 0 none.
  u.eye = glm::uvec4(uint32_t(eye * eyeSize.x),
                     uint32_t(std::lround(double(t.taa_share) * 65536.0)), 0, 0);
  return u;
}

TscmaaPass::TscmaaPass(vk::Context& ctx, const spec::CaseSpec& spec, CaptureSet captures)
    : ctx_(ctx),
      spec_(spec),
      eyeSize_(spec.render.width, spec.render.height),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE),
      linear_(ctx, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  const int eyes = eyeCount(spec);
  const glm::ivec2 wide = taa::outputSize(spec);
  edges_ = tscmaa::edgePipeline(ctx);
  cmaaPipeline_ = tscmaa::cmaaPipeline(ctx);
  taa_ = tscmaa::taaPipeline(ctx);
  mask_ = tscmaa::image(ctx, "tscmaa_mask", wide, VK_FORMAT_R32_UINT, tscmaa::kStorageCopy);
  cmaa_ = tscmaa::image(ctx, "tscmaa_cmaa", wide, VK_FORMAT_R16G16B16A16_SFLOAT, tscmaa::kAll);
  if (captures.has(Capture::Current))
    input_ = tscmaa::image(ctx, "tscmaa_input", wide, VK_FORMAT_R16G16B16A16_SFLOAT, tscmaa::kAll);
  if (eyes > 1)
    sideBySide_ =
        tscmaa::image(ctx, "tscmaa_output", wide, VK_FORMAT_R16G16B16A16_SFLOAT, tscmaa::kAll);
  stride_ = tscmaa::uniformStride(ctx);
  uniforms_ = vk::Buffer(ctx, stride_ * 2 * eyes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
  readback_ = vk::Buffer(ctx, sizeof(TscmaaCounts) * eyes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
  std::memset(readback_.mapped(), 0, sizeof(TscmaaCounts) * eyes);
  const uint32_t pixels = uint32_t(eyeSize_.x) * uint32_t(eyeSize_.y);
  eyes_.resize(size_t(eyes));
  for (int i = 0; i < eyes; ++i) {
    Eye& e = eyes_[size_t(i)];
    e.index = i;
    e.offset = glm::ivec2(i * eyeSize_.x, 0);
    e.edgeList = tscmaa::listBuffer(ctx, pixels);
    e.taaList = tscmaa::listBuffer(ctx, pixels);
    const std::string name = "tscmaa_history" + std::to_string(i);
    for (int h = 0; h < 2; ++h)
      e.history[h] = tscmaa::image(ctx, name + (h ? "b" : "a"), eyeSize_,
                                   VK_FORMAT_R16G16B16A16_SFLOAT, tscmaa::kAll);
    e.uniformOffset = stride_ * VkDeviceSize(2 * i);
    e.taaUniformOffset = e.uniformOffset + stride_;
  }
}

TscmaaPass::~TscmaaPass() = default;

vk::Image& TscmaaPass::output() {
  return sideBySide_ ? sideBySide_ : eyes_[0].history[current_];
}

glm::ivec2 TscmaaPass::outputSize() const {
  return taa::outputSize(spec_);
}

std::vector<StageCapture> TscmaaPass::captures() {
  const glm::ivec2 wide = outputSize();
  std::vector<StageCapture> out;
  if (input_) out.push_back({Capture::Current, &input_, wide});
  out.push_back({Capture::Cmaa, &cmaa_, wide});
  out.push_back({Capture::EdgeMask, &mask_, wide});
  return out;
}

std::vector<std::pair<std::string, double>> TscmaaPass::stats() const {
  return tscmaaCounters(counts());
}

std::vector<std::pair<std::string, double>> tscmaaCounters(
    const std::vector<TscmaaCounts>& counts) {
  double edges = 0.0, taaPixels = 0.0;
  for (const auto& c : counts) {
    edges += c.edges.count;
    taaPixels += c.taa.count;
  }
  return {{"tscmaa_edges", edges}, {"tscmaa_taa_pixels", taaPixels}};
}

std::vector<TscmaaCounts> TscmaaPass::counts() const {
  std::vector<TscmaaCounts> out(eyes_.size());
  std::memcpy(out.data(), readback_.mapped(), sizeof(TscmaaCounts) * out.size());
  return out;
}

std::vector<std::string> TscmaaPass::describe() const {
  const auto& t = spec_.tscmaa;
  char buf[256];
  std::snprintf(
      buf, sizeof(buf),
      "pass tscmaa: %d eye(s) of %dx%d, edge threshold %g, non-dominant removal %g, blurriness %g, "
      "taa share %g, history weight %g",
      int(eyes_.size()), eyeSize_.x, eyeSize_.y, double(t.edge_threshold),
      double(t.non_dominant_edge_removal), double(t.blurriness), double(t.taa_share),
      double(t.history_weight));
  std::vector<std::string> out{"pass tscmaa_edges",
                               "pass tscmaa_cmaa (indirect over the edge list)",
                               "pass tscmaa_taa (indirect over the TAA list)", buf};
  const size_t listBytes = size_t(eyes_[0].edgeList.size());
  out.push_back("buffer tscmaa lists 2x" + std::to_string(eyes_.size()) + " (" +
                std::to_string(listBytes / 1024) + " KiB each)");
  for (const vk::Image* i : {&mask_, &cmaa_, &input_, &sideBySide_, &eyes_[0].history[0]})
    if (*i) out.push_back(tscmaa::describeImage(*i));
  return out;
}

void TscmaaPass::record(VkCommandBuffer cmd, vk::GpuTimer& timer, const script::FrameState& s,
                        int eye, const ResolveInputs& in) {
  if (!in[ResolveInput::Color] || !in[ResolveInput::Depth])
    throw std::logic_error("TscmaaPass: colour or depth missing");
  vk::Image& color = *in[ResolveInput::Color];
  vk::Image& depth = *in[ResolveInput::Depth];
  Eye& e = eyes_.at(size_t(eye));
  if (eye == 0) current_ ^= 1;
  auto* base = static_cast<uint8_t*>(uniforms_.mapped());
  const gpu::TscmaaUniforms u = makeTscmaaUniforms(spec_.tscmaa, eyeSize_, eye);
  std::memcpy(base + e.uniformOffset, &u, sizeof(u));
  const gpu::TaaUniforms t = tscmaa::taaUniforms(s, eyeSize_, spec_.tscmaa.history_weight);
  std::memcpy(base + e.taaUniformOffset, &t, sizeof(t));
  const std::string suffix = eye ? ".eye" + std::to_string(eye) : "";
  auto scope = [&](const char* name, auto&& body) {
    timer.begin(cmd, name + suffix);
    body();
    timer.end(cmd);
  };
  if (input_) copyRegion(cmd, color, {0, 0}, input_, e.offset, eyeSize_);
  scope("tscmaa_edges", [&] { detectEdges(cmd, e, color); });
  scope("tscmaa_cmaa", [&] { antialias(cmd, e, color); });
  e.hasHistory = e.hasHistory && !s.resetHistory;
  scope("tscmaa_taa", [&] { temporal(cmd, e, depth); });
  e.hasHistory = true;
  if (sideBySide_) copyRegion(cmd, e.history[current_], {0, 0}, sideBySide_, e.offset, eyeSize_);
  // The headers go to the host for counts() once the frame completed.
  vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_READ_BIT);
  const VkDeviceSize slot = sizeof(TscmaaCounts) * VkDeviceSize(eye);
  const VkBufferCopy edgeCopy{0, slot, sizeof(gpu::EdgeListHeader)};
  const VkBufferCopy taaCopy{0, slot + sizeof(gpu::EdgeListHeader), sizeof(gpu::EdgeListHeader)};
  vkCmdCopyBuffer(cmd, e.edgeList.handle(), readback_.handle(), 1, &edgeCopy);
  vkCmdCopyBuffer(cmd, e.taaList.handle(), readback_.handle(), 1, &taaCopy);
  vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void TscmaaPass::detectEdges(VkCommandBuffer cmd, Eye& e, vk::Image& color) {
  // Last frame's indirect reads and header copies are done before the lists restart.
  vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT,
                    VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  const gpu::EdgeListHeader empty{0, 1, 1, 0};
  vkCmdUpdateBuffer(cmd, e.edgeList.handle(), 0, sizeof(empty), &empty);
  vkCmdUpdateBuffer(cmd, e.taaList.handle(), 0, sizeof(empty), &empty);
  vk::Dispatch(edges_)
      .after(VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
             VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
             VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT)
      .uniform(TSCMAA_BINDING_UNIFORMS, uniforms_.handle(), e.uniformOffset,
               sizeof(gpu::TscmaaUniforms))
      .sample(TSCMAA_BINDING_COLOR, color, point_.handle())
      .store(TSCMAA_BINDING_MASK, mask_)
      .storageBuffer(TSCMAA_BINDING_EDGE_LIST, e.edgeList.handle())
      .storageBuffer(TSCMAA_BINDING_TAA_LIST, e.taaList.handle())
      .record(ctx_, cmd, uint32_t(eyeSize_.x), uint32_t(eyeSize_.y));
  vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

void TscmaaPass::antialias(VkCommandBuffer cmd, Eye& e, vk::Image& color) {
  // Pixels off the edge list keep their colour: copied first, then the list overwrites.
  copyRegion(cmd, color, {0, 0}, cmaa_, e.offset, eyeSize_);
  vk::Dispatch(cmaaPipeline_)
      .uniform(TSCMAA_BINDING_UNIFORMS, uniforms_.handle(), e.uniformOffset,
               sizeof(gpu::TscmaaUniforms))
      .sample(TSCMAA_BINDING_COLOR, color, point_.handle())
      .load(TSCMAA_BINDING_MASK, mask_)
      .storageBuffer(TSCMAA_BINDING_EDGE_LIST, e.edgeList.handle())
      .store(TSCMAA_BINDING_CMAA, cmaa_)
      .recordIndirect(ctx_, cmd, e.edgeList.handle(), 0);
}

void TscmaaPass::temporal(VkCommandBuffer cmd, Eye& e, vk::Image& depth) {
  // Pixels off the TAA list take the CMAA result; without history, every pixel does.
  vk::Image& next = e.history[current_];
  vk::Image& previous = e.history[current_ ^ 1];
  copyRegion(cmd, cmaa_, e.offset, next, {0, 0}, eyeSize_);
  if (!e.hasHistory) return;
  vk::Dispatch(taa_)
      .uniform(TSCMAA_BINDING_UNIFORMS, uniforms_.handle(), e.uniformOffset,
               sizeof(gpu::TscmaaUniforms))
      .uniform(TSCMAA_BINDING_TAA_UNIFORMS, uniforms_.handle(), e.taaUniformOffset,
               sizeof(gpu::TaaUniforms))
      .storageBuffer(TSCMAA_BINDING_TAA_LIST, e.taaList.handle())
      .sample(TSCMAA_BINDING_CMAA, cmaa_, point_.handle())
      .sample(TSCMAA_BINDING_DEPTH, depth, point_.handle())
      .sample(TSCMAA_BINDING_HISTORY, previous, linear_.handle())
      .store(TSCMAA_BINDING_HISTORY_OUT, next)
      .recordIndirect(ctx_, cmd, e.taaList.handle(), 0);
}

}  // namespace taa
