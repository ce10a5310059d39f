#include "renderer.h"

#include <algorithm>
#include <cstring>
#include <optional>

#include "core/image_io.h"
#include "draw_list.h"
#include "frame_readback.h"
#include "frame_uniforms.h"
#include "gpu_scene.h"
#include "pass_plan.h"
#include "passes/adaptive/adaptive.h"
#include "passes/gbuffer.h"
#include "passes/inject.h"
#include "passes/reference.h"
#include "passes/taa_resolve.h"
#include "passes/tscmaa.h"
#include "post_chain.h"
#include "prev_gbuffer.h"
#include "readback.h"
#include "script/frame_state.h"
#include "spec/taa_modes.h"
#include "stereo.h"
#include "user/user_resolve.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/timestamps.h"
#include "vk/transfer.h"

namespace taa {

namespace {

// The largest render size over the run: targets are allocated once at this size and
// dynamic-resolution frames draw into their top-left corner.
glm::ivec2 maxRenderSize(const spec::CaseSpec& spec) {
  glm::ivec2 size(0);
  std::vector<int> probe = {0};
  for (const auto& k : spec.render.scale_schedule) probe.push_back(k.frame);
  for (int f : probe) size = glm::max(size, script::frameState(spec, f).renderSize);
  return size;
}

GBufferConfig gbufferConfig(const spec::CaseSpec& spec, const PassPlan& plan) {
  GBufferConfig c;
  const glm::ivec2 size = maxRenderSize(spec);
  c.width = uint32_t(size.x);
  c.height = uint32_t(size.y);
  c.deferred = plan.deferred;
  c.velocity = plan.velocity;
  c.normal = plan.normal;
  c.ids = plan.ids;
  return c;
}

PassPlan planWithCaptures(const spec::CaseSpec& spec, const RenderOptions& o,
                          const std::optional<UserShader>& user) {
  PassPlan p = planPasses(spec);
  if (user) addUserNeeds(p, user->interface);
  p.ids = p.ids || o.captureIds;
  p.velocity = p.velocity || o.captureVelocity;
  return p;
}

std::unique_ptr<TaaResolvePass> makeResolve(vk::Context& ctx, const spec::CaseSpec& spec, const PassPlan& plan) {
  if (!spec::modeRule(spec.taa.mode).resolve) return nullptr;  // off, or TSCMAA's passes instead
  if (!spec.taa.shader.empty()) return nullptr;                 // the user's resolve instead
  return std::make_unique<TaaResolvePass>(ctx, spec, plan);
}

std::unique_ptr<TscmaaPass> makeTscmaa(vk::Context& ctx, const spec::CaseSpec& spec,
                                       const RenderOptions& o) {
  if (!spec::modeRule(spec.taa.mode).tscmaa) return nullptr;
  return std::make_unique<TscmaaPass>(ctx, spec, o.captureCurrent);
}

std::optional<UserShader> loadUser(const spec::CaseSpec& spec) {
  if (spec.taa.shader.empty()) return std::nullopt;
  return loadUserShader(spec);
}

std::unique_ptr<UserResolvePass> makeUser(vk::Context& ctx, const spec::CaseSpec& spec,
                                          std::optional<UserShader>& shader) {
  if (!shader) return nullptr;
  return std::make_unique<UserResolvePass>(ctx, spec, std::move(*shader));
}

// One FrameUniforms slot per eye, at the device's uniform offset alignment.
VkDeviceSize uniformStride(vk::Context& ctx) {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(ctx.physical(), &props);
  const VkDeviceSize align = props.limits.minUniformBufferOffsetAlignment;
  return (sizeof(gpu::FrameUniforms) + align - 1) / align * align;
}

}  // namespace

struct Renderer::State {
  vk::Context& ctx;
  const spec::CaseSpec& spec;
  const scene::Scene& scene;
  RenderOptions options;
  GpuScene gpuScene;
  std::optional<UserShader> userShader;  // moved into `user` once the plan has its needs
  PassPlan plan;
  GBufferConfig config;
  GBufferTargets targets;
  GBufferPass gbuffer;
  PrevGBuffer prev;
  std::unique_ptr<TaaResolvePass> resolve;
  std::unique_ptr<UserResolvePass> user;
  std::unique_ptr<AdaptivePass> adaptive;
  std::unique_ptr<TscmaaPass> tscmaa;
  PostChain post;
  std::unique_ptr<ReferencePass> reference;
  std::unique_ptr<InjectPass> inject;
  VkDeviceSize uniformStride;
  vk::Buffer frameUniforms;  // one slot per eye
  vk::Buffer instances;
  vk::GpuTimer timer;
  FrameReadback readback;
  std::vector<std::string> log;
  int nextFrame = 0;

  State(vk::Context& c, const spec::CaseSpec& s, const scene::Scene& sc, RenderOptions o)
      : ctx(c),
        spec(s),
        scene(sc),
        options(o),
        gpuScene(c, sc),
        userShader(loadUser(s)),
        plan(planWithCaptures(s, o, userShader)),
        config(gbufferConfig(s, plan)),
        targets(c, config),
        gbuffer(c, gpuScene, config),
        prev(c, plan, targets),
        resolve(makeResolve(c, s, plan)),
        user(makeUser(c, s, userShader)),
        adaptive(plan.adaptive ? std::make_unique<AdaptivePass>(
                                     c, s, gpuScene, buildDrawList(sc, script::frameState(s, 0)),
                                     o.captureAdaptive)
                               : nullptr),
        tscmaa(makeTscmaa(c, s, o)),
        post(c, s, plan, maxRenderSize(s)),
        reference(o.reference ? std::make_unique<ReferencePass>(c, s, gpuScene) : nullptr),
        inject(s.inject.frames.empty() ? nullptr : std::make_unique<InjectPass>(c, s)),
        uniformStride(taa::uniformStride(c)),
        frameUniforms(c, uniformStride * VkDeviceSize(eyeCount(s)),
                      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
        instances(
            c,
            std::max<size_t>(1, buildDrawList(sc, script::frameState(s, 0)).instances.size()) *
                sizeof(gpu::InstanceData),
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true),
        timer(c),
        readback(c) {
    log.push_back("device: " + c.info().name + " (" + c.info().driverInfo + ")");
    for (const auto& note : sc.notes) log.push_back("scene note: " + note);
    for (const auto& p : plan.describe()) log.push_back(p);
    if (resolve) log.push_back(resolve->describe());
    if (user)
      for (const auto& line : user->describe()) log.push_back(line);
    if (adaptive)
      for (const auto& p : adaptive->describe()) log.push_back(p);
    if (tscmaa)
      for (const auto& line : tscmaa->describe()) log.push_back(line);
    for (const auto& p : post.describe()) log.push_back(p);
    if (inject) log.push_back("pass inject (stress: non-finite colour on listed frames)");
    if (reference)
      log.push_back("pass reference (" + std::to_string(reference->samples()) + " samples at " +
                    std::to_string(s.render.width) + "x" + std::to_string(s.render.height) +
                    " per eye)");
    for (const auto& t : targets.describe()) log.push_back("buffer " + t);
    for (const auto& t : prev.describe()) log.push_back("buffer " + t);
    if (resolve) log.push_back("buffer history 2x " + std::to_string(s.render.width) + "x" + std::to_string(s.render.height));
    log.push_back("scene: " + std::to_string(sc.vertices.size()) + " vertices, " +
                  std::to_string(sc.indices.size() / 3) + " triangles, " + std::to_string(sc.textures.size()) +
                  " textures (" + std::to_string(gpuScene.textureBytes() / 1024) + " KiB)");
  }
};

Renderer::Renderer(vk::Context& ctx, const spec::CaseSpec& spec, const scene::Scene& scene, RenderOptions options)
    : s_(std::make_unique<State>(ctx, spec, scene, options)) {}

Renderer::~Renderer() = default;

const std::vector<std::string>& Renderer::log() const { return s_->log; }

FrameRecord Renderer::renderFrame(int frame, bool readImages) {
  auto& s = *s_;
  if (frame != s.nextFrame)
    throw std::logic_error("Renderer: frame " + std::to_string(frame) + " requested, expected " +
                           std::to_string(s.nextFrame));
  ++s.nextFrame;
  const script::FrameState state = script::frameState(s.spec, frame);
  const DrawList draws = buildDrawList(s.scene, state);
  std::memcpy(s.instances.mapped(), draws.instances.data(), draws.instances.size() * sizeof(gpu::InstanceData));
  s.gpuScene.uploadDeformed(draws.deformed, draws.deformedPrev);
  const int eyes = eyeCount(s.spec);

  const bool lodBiasApplies = !s.spec.material.lod_bias_taa_only || s.plan.taa;
  const float lodBias = lodBiasApplies ? s.spec.material.lod_bias : 0.0f;
  s.timer.reset();
  VkCommandBuffer cmd = s.ctx.beginCommands();
  vk::Image* resolveInput = nullptr;
  // Stereo renders the G-buffer once per eye; everything else has one eye.
  for (int eye = 0; eye < eyes; ++eye) {
    const script::FrameState eyeState =
        eyeFrameState(state, eye, eyes, s.spec.tscmaa.eye_separation);
    const gpu::FrameUniforms uniforms = makeFrameUniforms(eyeState, s.spec.lighting);
    const VkDeviceSize slot = s.uniformStride * VkDeviceSize(eye);
    std::memcpy(static_cast<uint8_t*>(s.frameUniforms.mapped()) + slot, &uniforms,
                sizeof(uniforms));
    s.timer.begin(cmd, eye ? "gbuffer.eye" + std::to_string(eye) : "gbuffer");
    s.gbuffer.record(cmd, s.targets, draws, s.frameUniforms.handle(), slot, s.instances.handle(),
                     state.renderSize, lodBias);
    s.timer.end(cmd);
    if (s.inject && s.inject->appliesTo(frame)) s.inject->record(cmd, s.targets.color);
    resolveInput = &s.post.beforeResolve(cmd, s.timer, eyeState, s.targets);
    if (s.tscmaa) s.tscmaa->record(cmd, &s.timer, eyeState, eye, *resolveInput, s.targets.depth);
  }
  vk::Image* output = resolveInput;
  glm::ivec2 outSize = state.renderSize;
  if (s.tscmaa) {
    output = &s.tscmaa->output();
    outSize = outputSize(s.spec);
  } else if (s.user) {
    ResolveInputs in;
    in.color = resolveInput;
    in.depth = &s.targets.depth;
    in.velocity = s.targets.velocity ? &s.targets.velocity : nullptr;
    in.ids = s.targets.ids ? &s.targets.ids : nullptr;
    in.normal = s.targets.normal ? &s.targets.normal : nullptr;
    in.prevDepth = s.prev.depth ? &s.prev.depth : nullptr;
    in.prevNormal = s.prev.normal ? &s.prev.normal : nullptr;
    in.prevIds = s.prev.ids ? &s.prev.ids : nullptr;
    s.user->record(cmd, s.timer, state, 0, in);
    output = &s.user->output();
    outSize = s.user->outputSize();
    s.prev.capture(cmd, s.targets);
  } else if (s.resolve) {
    TaaInputs in;
    in.color = resolveInput;
    in.depth = &s.targets.depth;
    in.velocity = s.targets.velocity ? &s.targets.velocity : nullptr;
    in.ids = s.targets.ids ? &s.targets.ids : nullptr;
    in.normal = s.targets.normal ? &s.targets.normal : nullptr;
    in.prevDepth = s.prev.depth ? &s.prev.depth : nullptr;
    in.prevNormal = s.prev.normal ? &s.prev.normal : nullptr;
    in.prevIds = s.prev.ids ? &s.prev.ids : nullptr;
    in.prevVelocity = s.prev.velocity ? &s.prev.velocity : nullptr;
    s.timer.begin(cmd, "taa_resolve");
    s.resolve->record(cmd, state, in);
    s.timer.end(cmd);
    output = &s.resolve->output();
    outSize = glm::ivec2(s.spec.render.width, s.spec.render.height);
    if (s.adaptive) {
      const SegmentationInputs seg{resolveInput, &s.targets.depth, &s.targets.normal, &s.targets.ids,
                                   s.resolve->rejection(), nullptr};
      const AdaptiveFrame af{&state, &draws, s.frameUniforms.handle(), lodBias};
      output = &s.adaptive->record(cmd, s.timer, af, seg, *output);
    }
    s.prev.capture(cmd, s.targets);
  }
  output = &s.post.afterResolve(cmd, s.timer, state, *output, outSize);
  // The reference is only ever read back with the frame's images; rendering it for other
  // frames would cost reference.samples scene renders each for nothing.
  if (s.reference && readImages) {
    s.timer.begin(cmd, "reference");
    for (int eye = 0; eye < eyes; ++eye)
      s.reference->record(cmd, eyeFrameState(state, eye, eyes, s.spec.tscmaa.eye_separation), draws,
                          s.instances.handle(), eye);
    s.timer.end(cmd);
  }
  // A debug view replaces the output (after the passes it would otherwise feed).
  if (s.resolve && s.resolve->debugView()) output = s.resolve->debugView();
  if (s.adaptive && s.adaptive->debugView()) output = s.adaptive->debugView();
  const bool readOutput = readImages || s.options.hashEveryFrame;
  if (readOutput) {
    FrameSources src;
    src.output = output;
    src.outputSize = outSize;
    src.renderSize = state.renderSize;
    src.resolveInput = resolveInput;
    src.targets = &s.targets;
    src.tscmaa = s.tscmaa.get();
    src.reference = s.reference.get();
    src.adaptive = s.adaptive.get();
    s.readback.record(cmd, s.spec, s.options, src, readImages);
  }
  s.ctx.submitAndWait(cmd);

  FrameRecord record;
  record.frame = frame;
  record.renderSize = state.renderSize;
  record.cameraCut = state.cameraCut;
  record.historyReset = state.resetHistory;
  record.gpuMs = s.timer.read();
  if (s.tscmaa) record.stats = tscmaaCounters(s.tscmaa->counts());
  if (s.adaptive) record.stats = s.adaptive->stats();
  if (readOutput) s.readback.finish(record);
  return record;
}

void renderSequence(Renderer& renderer, const spec::CaseSpec& spec, const std::function<void(FrameRecord&)>& sink,
                    const std::function<void(int)>& progress) {
  const auto& wanted = spec.output.frames;
  for (int f = 0; f < spec.script.frames; ++f) {
    if (progress) progress(f);
    FrameRecord record = renderer.renderFrame(f, std::binary_search(wanted.begin(), wanted.end(), f));
    sink(record);
  }
}

}  // namespace taa
