#include "passes/taa_resolve.h"

#include <cstring>
#include <glm/matrix.hpp>
#include <iterator>
#include <stdexcept>

#include "passes/storage_image.h"
#include "passes/taa_moving.h"
#include "spec/taa_modes.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

namespace {

using namespace spec;

// Bound where a variant reads nothing (cleared, so a stray read sees zeros).
vk::Image dummy(vk::Context& ctx, VkFormat format, vk::Use use = vk::Use::SampledCompute) {
  vk::ImageDesc d;
  d.name = "dummy";
  d.format = format;
  d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
  return zeroedImage(ctx, d, use);
}

// One eye: the resolve never runs in stereo (TSCMAA replaces it there).
glm::ivec2 resolveOutputSize(const CaseSpec& s) {
  return {s.render.width, s.render.height};
}

// Every specialization id of taa_settings.h, the settings' and the resolve's own, is unique.
constexpr bool taaSpecIdsUnique() {
#define TAA_ID_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) id,
#define TAA_ID_B(key, def, id, name, modes, reads, rule, text, doc, impl) id,
#define TAA_ID_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl)
#define TAA_ID_OWN(id, type, name, def) id,
  constexpr int ids[] = {TAA_RESOLVE_CONSTANTS(TAA_ID_OWN)
                             TAA_SETTINGS(TAA_ID_E, TAA_ID_B, TAA_ID_F)};
#undef TAA_ID_E
#undef TAA_ID_B
#undef TAA_ID_F
#undef TAA_ID_OWN
  for (size_t a = 0; a < std::size(ids); ++a)
    for (size_t b = a + 1; b < std::size(ids); ++b)
      if (ids[a] == ids[b]) return false;
  return true;
}
static_assert(taaSpecIdsUnique(),
              "two specialization constants share an id in common/taa_settings.h");

// Likewise every float setting's uniform slot, within TaaUniforms::settings.
constexpr bool taaSlotsValid() {
#define TAA_SLOT_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_SLOT_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_SLOT_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) slot,
  constexpr int slots[] = {TAA_SETTINGS(TAA_SLOT_E, TAA_SLOT_B, TAA_SLOT_F)};
#undef TAA_SLOT_E
#undef TAA_SLOT_B
#undef TAA_SLOT_F
  for (size_t a = 0; a < std::size(slots); ++a) {
    if (slots[a] < 0 || slots[a] >= 4 * TAA_SETTING_VEC4S) return false;
    for (size_t b = a + 1; b < std::size(slots); ++b)
      if (slots[a] == slots[b]) return false;
  }
  return true;
}
static_assert(taaSlotsValid(),
              "uniform slots in common/taa_settings.h overlap or exceed TAA_SETTING_VEC4S");

static_assert(resolveInputBindingsValid({TAA_BINDING_UNIFORMS, TAA_BINDING_HISTORY_OUT,
                                          TAA_BINDING_DEBUG_OUT, TAA_BINDING_REJECT_OUT},
                                         {}),
              "two resolve inputs share a binding in common/resolve_inputs.h, or one takes the "
              "uniforms' or an output's (common/shared.h)");

// The settings the resolve runs: with motion blur off nothing writes the speed into alpha,
// so velocity_in_alpha falls back to the per-pixel velocities, as seed 001's TAA does.
TaaSpec resolveTaa(const CaseSpec& spec) {
  TaaSpec t = effectiveTaa(spec.taa);
  if (!spec.post.motion_blur) t.velocity_in_alpha = false;
  return t;
}

VkFormat historyFormat(const TaaSpec& t) {
  return t.history_format == HistoryFormat::Rgba32f ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                    : VK_FORMAT_R16G16B16A16_SFLOAT;
}

}  // namespace

ResolveInputSet taaResolveInputs(const CaseSpec& spec) {
  const ModeRule& rule = modeRule(spec.taa.mode);
  if (!rule.resolve) return {};
  const TaaSpec effective = resolveTaa(spec);
  // Every path reads the colour and all but pass-through their history; a setting adds what
  // its row reads where the path runs it (the specialization constants' rule, below).
  const uint32_t inPath = pathModes(rule.path);
  ResolveInputSet reads = {ResolveInput::Color};
  if (rule.path != Resolve::PassThrough) reads |= {ResolveInput::History};
#define TAA_READS_E(key, type, values, def, id, name, modes, settingReads, rule, text, doc, impl) \
  if (modes & inPath) reads |= settingReads(effective);
#define TAA_READS_B(key, def, id, name, modes, settingReads, rule, text, doc, impl) \
  if (modes & inPath) reads |= settingReads(effective);
#define TAA_READS_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl)
  TAA_SETTINGS(TAA_READS_E, TAA_READS_B, TAA_READS_F)
#undef TAA_READS_E
#undef TAA_READS_B
#undef TAA_READS_F
  return reads;
}

std::vector<ResolveRead> taaResolveReads(const CaseSpec& spec) {
  const ResolveInputSet reads = taaResolveInputs(spec);
  // The formats gbuffer.cpp, prev_gbuffer.cpp and motion_blur.cpp allocate; record() checks
  // them against the images it binds.
  std::vector<ResolveRead> r;
  for (const ResolveInputInfo& i : kResolveInputs)
    if (reads.has(i.input))
      r.push_back({i.name, vk::formatBytes(i.format == VK_FORMAT_UNDEFINED
                                               ? historyFormat(resolveTaa(spec))
                                               : i.format)});
  return r;
}

uint32_t taaResolveReadBytes(const CaseSpec& spec) {
  uint32_t bytes = 0;
  for (const auto& r : taaResolveReads(spec)) bytes += r.bytes;
  return bytes;
}

vk::SpecConstants taaSpecConstants(const CaseSpec& spec, bool hasHistory) {
  const TaaSpec t = resolveTaa(spec);
  const Resolve path = modeRule(t.mode).path;
  // A setting the path has no use for gets 0, so a pipeline depends only on what it runs.
  const uint32_t inPath = pathModes(path);
  const bool upsample = spec.render.upsample != 1.0f || !spec.render.scale_schedule.empty();
  vk::SpecConstants c;
  c.set(TAA_SPEC_RESOLVE, int(path))
      .set(TAA_SPEC_HAS_HISTORY, hasHistory)
      .set(TAA_SPEC_UPSAMPLE, upsample)
      .set(TAA_SPEC_DEBUG, int(spec.debug.output))
      .set(TAA_SPEC_REJECT_MASK, modeRule(t.mode).adaptive);
#define TAA_SPEC_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  c.set(id, (modes & inPath) ? int(t.key) : 0);
#define TAA_SPEC_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  c.set(id, (modes & inPath) != 0 && t.key);
#define TAA_SPEC_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl)
  TAA_SETTINGS(TAA_SPEC_E, TAA_SPEC_B, TAA_SPEC_F)
#undef TAA_SPEC_E
#undef TAA_SPEC_B
#undef TAA_SPEC_F
  return c;
}

gpu::TaaUniforms makeTaaUniforms(const CaseSpec& spec, const script::FrameState& s,
                                 glm::ivec2 prevRenderSize) {
  // taa.moving blends the float settings by the camera's speed; without it, the still ones.
  const TaaSpec t = blendMoving(spec.taa, movingWeight(spec.taa.moving, s));
  gpu::TaaUniforms u{};
  u.invViewProj = glm::inverse(s.camera.viewProjection);
  u.prevViewProj = s.prevCamera.viewProjection;
  const glm::vec2 render(s.renderSize), prev(prevRenderSize), out(resolveOutputSize(spec));
  u.renderSize = glm::vec4(render, 1.0f / render);
  u.prevRenderSize = glm::vec4(prev, 1.0f / prev);
  u.outputSize = glm::vec4(out, 1.0f / out);
  u.jitter = glm::vec4(s.jitter, float(s.frame), 0.0f);  // z: the frame index (taa.noise)
  u.view = glm::vec4(s.camera.nearPlane, s.camera.farPlane, spec.debug.scale, 0.0f);
#define TAA_PARAM_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_PARAM_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_PARAM_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  u.settings[slot / 4][slot % 4] = t.key;
  TAA_SETTINGS(TAA_PARAM_E, TAA_PARAM_B, TAA_PARAM_F)
#undef TAA_PARAM_E
#undef TAA_PARAM_B
#undef TAA_PARAM_F
  return u;
}

GBufferNeeds taaResolveNeeds(const CaseSpec& spec) {
  return gbufferNeeds(taaResolveInputs(spec));
}

TaaResolvePass::TaaResolvePass(vk::Context& ctx, const CaseSpec& spec, const PassPlan& plan)
    : ctx_(ctx),
      spec_(spec),
      dummyFloat_(dummy(ctx, VK_FORMAT_R16G16B16A16_SFLOAT)),
      dummyUint_(dummy(ctx, VK_FORMAT_R32_UINT)),
      dummyStorage_(dummy(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, vk::Use::StorageWrite)),
      dummyReject_(dummy(ctx, VK_FORMAT_R32_UINT, vk::Use::StorageWrite)),
      uniforms_(ctx, sizeof(gpu::TaaUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
      linear_(ctx, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  withHistory_ = vk::createComputePipeline(ctx, "taa_resolve.comp", taaSpecConstants(spec, true));
  withoutHistory_ =
      vk::createComputePipeline(ctx, "taa_resolve.comp", taaSpecConstants(spec, false));
  const VkFormat format = historyFormat(effectiveTaa(spec.taa));
  history_[0] = storageImage(ctx, "history_a", resolveOutputSize(spec), format);
  history_[1] = storageImage(ctx, "history_b", resolveOutputSize(spec), format);
  // The segmentation view is drawn by the adaptive pass, not here.
  if (plan.debugView && spec.debug.output != DebugOutput::Segmentation)
    debug_ =
        storageImage(ctx, "debug_view", resolveOutputSize(spec), VK_FORMAT_R16G16B16A16_SFLOAT);
  if (plan.adaptive)
    rejection_ = storageImage(ctx, "rejection", resolveOutputSize(spec), VK_FORMAT_R32_UINT);
}

glm::ivec2 TaaResolvePass::outputSize() const {
  return resolveOutputSize(spec_);
}

std::vector<std::string> TaaResolvePass::describe() const {
  const glm::ivec2 size = resolveOutputSize(spec_);
  std::vector<std::string> out = {
      "pass taa_resolve", "taa_resolve spec constants: " + taaSpecConstants(spec_, true).describe(),
      "buffer history 2x " + std::to_string(size.x) + "x" + std::to_string(size.y)};
  if (spec_.taa.velocity_in_alpha && !spec_.post.motion_blur)
    out.push_back(
        "taa_resolve: taa.velocity_in_alpha falls back to the velocity buffer, "
        "post.motion_blur is off so nothing writes the speed into alpha (seed 001)");
  std::string reads;
  for (const auto& r : taaResolveReads(spec_))
    reads += (reads.empty() ? "" : " + ") + r.name + " " + std::to_string(r.bytes);
  out.push_back("taa_resolve reads per pixel: " + reads + " = " +
                std::to_string(taaResolveReadBytes(spec_)) + " bytes");
  return out;
}

// The bytes-per-pixel figure describe() logs is the formats of the images bound here.
void TaaResolvePass::checkResolveReads(const ResolveInputs& in, ResolveInputSet reads) const {
  uint32_t bytes = 0;
  for (const ResolveInputInfo& i : kResolveInputs)
    if (reads.has(i.input) && in[i.input]) bytes += vk::formatBytes(in[i.input]->desc().format);
  if (bytes != taaResolveReadBytes(spec_))
    throw std::logic_error("TaaResolvePass: the bound images read " + std::to_string(bytes) +
                           " bytes a pixel, taaResolveReads says " +
                           std::to_string(taaResolveReadBytes(spec_)));
}

void TaaResolvePass::record(VkCommandBuffer cmd, vk::GpuTimer& timer,
                            const script::FrameState& state, int eye, const ResolveInputs& in) {
  if (eye != 0) throw std::logic_error("TaaResolvePass: the built-in resolve has one eye");
  timer.begin(cmd, "taa_resolve");
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
  const ResolveInputSet reads = taaResolveInputs(spec_);
  ResolveInputs bound = in;
  for (const ResolveInputInfo& i : kResolveInputs)
    if (i.source == InputSource::Own) bound[i.input] = &previous;
  checkResolveReads(bound, reads);
  // An input the settings do not read gets a zeroed stand-in even where the plan allocated
  // it for another pass (depth is always rendered), so the colour-only resolve (seed 001)
  // provably takes no depth and a shader reading what its row does not name reads zeros.
  for (const ResolveInputInfo& i : kResolveInputs) {
    vk::Image* image = reads.has(i.input) ? bound[i.input] : nullptr;
    vk::Image& standIn = i.uintTexels ? dummyUint_ : dummyFloat_;
    d.sample(i.binding, image ? *image : standIn,
             i.filter == VK_FILTER_LINEAR ? linear_.handle() : point_.handle());
  }
  d.store(TAA_BINDING_HISTORY_OUT, next)
      .store(TAA_BINDING_DEBUG_OUT, debug_ ? debug_ : dummyStorage_)
      .store(TAA_BINDING_REJECT_OUT, rejection_ ? rejection_ : dummyReject_)
      .record(ctx_, cmd, uint32_t(spec_.render.width), uint32_t(spec_.render.height));
  timer.end(cmd);
}

}  // namespace taa
