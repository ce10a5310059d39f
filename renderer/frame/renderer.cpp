#include "api/renderer.h"

#include <algorithm>
#include <cstring>
#include <set>

#include "api/device.h"
#include "api/device_error.h"
#include "api/reference_cache.h"
#include "frame/draw_list.h"
#include "frame/frame_readback.h"
#include "frame/frame_uniforms.h"
#include "frame/gpu_scene.h"
#include "frame/pass_plan.h"
#include "frame/post_chain.h"
#include "frame/prev_gbuffer.h"
#include "frame/resolve_factory.h"
#include "passes/gbuffer.h"
#include "passes/inject.h"
#include "passes/post_filter.h"
#include "passes/reference.h"
#include "passes/shadow.h"
#include "passes/still_image.h"
#include "script/frame_state.h"
#include "script/stereo.h"
#include "vk/context.h"
#include "vk/timestamps.h"

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

// The G-buffer: the targets the built passes read, and the scene settings its shading uses.
GBufferConfig gbufferConfig(const spec::CaseSpec& spec, const PassPlan& plan,
                            const GBufferNeeds& needs, ShadowPass* shadow) {
  GBufferConfig c = planGBuffer(plan, needs, maxRenderSize(spec));
  applyShadingSettings(c, spec, shadow);
  return c;
}

// The targets no pass reads but the harness's captures do.
PassPlan planWithCaptures(const spec::CaseSpec& spec, const RenderOptions& o) {
  PassPlan p = planPasses(spec);
  p.own.ids = p.own.ids || o.captures.has(Capture::Ids);
  p.own.velocity = p.own.velocity || o.captures.has(Capture::Velocity);
  return p;
}

// What the resolve may read this frame: the images the plan allocated, null otherwise.
ResolveInputs resolveInputs(GBufferTargets& t, PrevGBuffer& prev, vk::Image& color) {
  auto orNull = [](vk::Image& image) { return image ? &image : nullptr; };
  // Where each G-buffer image lives: this frame's targets and last frame's copies.
  const std::pair<bool GBufferNeeds::*, vk::Image*> images[] = {
      {&GBufferNeeds::depth, &t.depth},          {&GBufferNeeds::velocity, &t.velocity},
      {&GBufferNeeds::ids, &t.ids},              {&GBufferNeeds::normal, &t.normal},
      {&GBufferNeeds::prevDepth, &prev.depth},   {&GBufferNeeds::prevVelocity, &prev.velocity},
      {&GBufferNeeds::prevIds, &prev.ids},       {&GBufferNeeds::prevNormal, &prev.normal}};
  ResolveInputs in;
  for (const ResolveInputInfo& i : kResolveInputs) {
    if (i.source == InputSource::Color) in[i.input] = &color;
    for (const auto& [need, image] : images)
      if (i.source == InputSource::GBuffer && i.need == need) in[i.input] = orNull(*image);
  }
  return in;
}

// What the built passes read, beyond colour and depth.
GBufferNeeds passNeeds(const ResolveStage* resolve, const PostChain& post) {
  GBufferNeeds n = post.needs();
  if (resolve) n |= resolve->needs();
  return n;
}

// debug.channels: a pass only when some channel is hidden from a debug view.
std::unique_ptr<PostFilter> makeDebugChannels(vk::Context& ctx, const spec::CaseSpec& spec) {
  if (spec.debug.output == spec::DebugOutput::None) return nullptr;
  glm::vec4 shown(0.0f);
  for (const spec::DebugChannel c : spec.debug.channels) shown[int(c)] = 1.0f;
  if (shown == glm::vec4(1.0f)) return nullptr;
  return std::make_unique<PostFilter>(ctx, "debug_channels.comp", shown);
}

// One FrameUniforms slot per eye, at the device's uniform offset alignment.
VkDeviceSize uniformStride(vk::Context& ctx) {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(ctx.physical(), &props);
  const VkDeviceSize align = props.limits.minUniformBufferOffsetAlignment;
  return (sizeof(gpu::FrameUniforms) + align - 1) / align * align;
}

}  // namespace

namespace {

// Builds a pass, adding the shaders it loads to `into`.
template <class Make>
auto recordingShaders(std::set<std::string>& into, Make make) {
  ShaderUseRecord record;
  auto pass = make();
  for (auto& name : record.names()) into.insert(std::move(name));
  return pass;
}

}  // namespace

struct Renderer::State {
  vk::Context& ctx;
  const spec::CaseSpec& spec;
  const scene::Scene& scene;
  RenderOptions options;
  GpuScene gpuScene;
  std::set<std::string> referenceShaders;  // of the passes the reference reads
  std::unique_ptr<ShadowPass> shadow;      // lighting.shadows
  float shadowDistance = 0.0f;
  std::unique_ptr<StillImagePass> still;  // debug.image
  std::unique_ptr<PostFilter> debugChannels;
  vk::Image debugChannelsOut;
  PassPlan plan;
  // The passes are built first: the G-buffer holds what they say they read.
  DrawList firstFrame;
  std::unique_ptr<ResolveStage> resolve;  // null when the mode runs none
  PostChain post;                         // the passes before, following and after it
  GBufferNeeds needs;
  GBufferConfig config;
  GBufferTargets targets;
  GBufferPass gbuffer;
  PrevGBuffer prev;
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
        shadow(recordingShaders(referenceShaders,
                                [&] {
                                  return s.lighting.shadows
                                             ? std::make_unique<ShadowPass>(
                                                   c, gpuScene, s.lighting.cascades,
                                                   s.render.lod0 || s.render.lod0_alpha_test)
                                             : nullptr;
                                })),
        still(recordingShaders(referenceShaders,
                               [&] {
                                 return s.debug.image.empty()
                                            ? nullptr
                                            : std::make_unique<StillImagePass>(c, sc.still);
                               })),
        debugChannels(makeDebugChannels(c, s)),
        plan(planWithCaptures(s, o)),
        firstFrame(buildDrawList(sc, script::frameState(s, 0))),
        resolve(makeResolveStage(c, s, plan, options)),
        post(PassContext{c, s, gpuScene, firstFrame, options}, plan, maxRenderSize(s)),
        needs(passNeeds(resolve.get(), post)),
        config(gbufferConfig(s, plan, needs, shadow.get())),
        targets(c, config),
        gbuffer(c, gpuScene, config),
        prev(c, needs, targets),
        reference(recordingShaders(referenceShaders,
                                   [&] {
                                     return o.captures.has(Capture::Reference)
                                                ? std::make_unique<ReferencePass>(
                                                      c, s, gpuScene, shadow.get(), still.get())
                                                : nullptr;
                                   })),
        inject(s.inject.frames.empty() ? nullptr : std::make_unique<InjectPass>(c, s)),
        uniformStride(taa::uniformStride(c)),
        frameUniforms(c, uniformStride * VkDeviceSize(eyeCount(s)),
                      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
        instances(c, std::max<size_t>(1, firstFrame.instances.size()) * sizeof(gpu::InstanceData),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true),
        timer(c),
        readback(c) {
    if (reference) reference->setShaders({referenceShaders.begin(), referenceShaders.end()});
    log.push_back("device: " + c.info().name + " (" + c.info().driverInfo + ")");
    for (const auto& note : sc.notes) log.push_back("scene note: " + note);
    for (const auto& model : sc.models)
      if (const std::string line = scene::describeAnimations(model); !line.empty())
        log.push_back("scene animations: " + line);
    if (debugChannels)
      debugChannelsOut = makePostImage(c, "debug_channels", {s.render.width, s.render.height});
    if (still)
      log.push_back("pass still_image (debug.image " + s.debug.image + ", " +
                    spec::enumToString(s.debug.image_sampling) + ")");
    if (shadow) {
      const script::FrameState first = script::frameState(s, 0);
      shadowDistance = taa::shadowDistance(first.camera, casterBounds(sc, firstFrame));
      log.push_back(shadow->describe());
    }
    for (const auto& p : plan.describe()) log.push_back(p);
    if (resolve)
      for (const auto& p : resolve->describe()) log.push_back(p);
    for (const auto& p : post.describe()) log.push_back(p);
    if (inject) log.push_back("pass inject (stress: non-finite colour on listed frames)");
    if (reference)
      log.push_back("pass reference (" + std::to_string(reference->samples()) + " samples at " +
                    std::to_string(s.render.width) + "x" + std::to_string(s.render.height) +
                    " per eye)");
    for (const auto& t : targets.describe()) log.push_back("buffer " + t);
    for (const auto& t : prev.describe()) log.push_back("buffer " + t);
    log.push_back("scene: " + std::to_string(sc.vertices.size()) + " vertices, " +
                  std::to_string(sc.indices.size() / 3) + " triangles, " +
                  std::to_string(sc.textures.size()) + " textures (" +
                  std::to_string(gpuScene.textureBytes() / 1024) + " KiB)");
    // Frame 0's draws only size what the constructor built (the instance buffer, the
    // tracer's static world, the shadow distance); kept, they would cost a second copy of
    // every instance for the whole run.
    firstFrame = DrawList();
  }
};

Renderer::Renderer(vk::Context& ctx, const spec::CaseSpec& spec, const scene::Scene& scene,
                   RenderOptions options) try
    : s_(std::make_unique<State>(ctx, spec, scene, options)) {
} catch (const UnsupportedSettingError& e) {
  throw UnsupportedSettingError(spec.file.string() + ": " + e.what());  // the case to fix
}

Renderer::~Renderer() = default;

const std::vector<std::string>& Renderer::log() const {
  return s_->log;
}

std::vector<std::string> Renderer::referenceShaders() const {
  return s_->reference ? s_->reference->shaders() : std::vector<std::string>{};
}

FrameRecord Renderer::renderFrame(int frame, bool readImages) {
  auto& s = *s_;
  if (frame != s.nextFrame)
    throw std::logic_error("Renderer: frame " + std::to_string(frame) + " requested, expected " +
                           std::to_string(s.nextFrame));
  ++s.nextFrame;
  const script::FrameState state = script::frameState(s.spec, frame);
  const DrawList draws = buildDrawList(s.scene, state);
  std::memcpy(s.instances.mapped(), draws.instances.data(),
              draws.instances.size() * sizeof(gpu::InstanceData));
  s.gpuScene.uploadDeformed(draws.deformed, draws.deformedPrev);
  const int eyes = eyeCount(s.spec);

  const bool lodBiasApplies = !s.spec.material.lod_bias_taa_only || s.plan.taa;
  const float lodBias = lodBiasApplies ? s.spec.material.lod_bias : 0.0f;
  s.timer.reset();
  VkCommandBuffer cmd = s.ctx.beginCommands();
  const FrameView view{cmd,    &s.timer, &state, &s.targets, &draws, s.frameUniforms.handle(),
                       lodBias};
  vk::Image* resolveInput = nullptr;
  // One shadow atlas a frame, fitted to the (centre) camera: both eyes and the reference
  // read the same shadows.
  ShadowCascades shadows;
  if (s.shadow) {
    shadows = shadowCascades(s.spec.lighting, state.camera, casterBounds(s.scene, draws),
                             s.shadowDistance);
    s.timer.begin(cmd, "shadow");
    s.shadow->record(cmd, shadows, draws, s.instances.handle());
    s.timer.end(cmd);
  }
  // Stereo renders the G-buffer, and resolves, once per eye; everything else has one eye.
  for (int eye = 0; eye < eyes; ++eye) {
    const script::FrameState eyeState =
        eyeFrameState(state, eye, eyes, s.spec.tscmaa.eye_separation);
    gpu::FrameUniforms uniforms = makeFrameUniforms(eyeState, s.spec.lighting);
    setShadowUniforms(uniforms, shadows);
    const VkDeviceSize slot = s.uniformStride * VkDeviceSize(eye);
    std::memcpy(static_cast<uint8_t*>(s.frameUniforms.mapped()) + slot, &uniforms,
                sizeof(uniforms));
    s.timer.begin(cmd, eye ? "gbuffer.eye" + std::to_string(eye) : "gbuffer");
    s.gbuffer.record(cmd, s.targets, draws, s.frameUniforms.handle(), slot, s.instances.handle(),
                     state.renderSize, lodBias);
    s.timer.end(cmd);
    if (s.still)
      s.still->record(cmd, s.targets.color, state.renderSize, state.jitter,
                      s.spec.debug.image_sampling == spec::ImageSampling::Nearest);
    if (s.inject && s.inject->appliesTo(frame)) s.inject->record(cmd, s.targets.color);
    FrameView eyeView = view;
    eyeView.state = &eyeState;
    resolveInput = &s.post.beforeResolve(eyeView, s.targets.color);
    if (s.resolve)
      s.resolve->record(cmd, s.timer, eyeState, eye,
                        resolveInputs(s.targets, s.prev, *resolveInput));
  }
  vk::Image* output = resolveInput;
  glm::ivec2 outSize = state.renderSize;
  if (s.resolve) {
    output = &s.post.followResolve(view, *s.resolve, *resolveInput);
    outSize = s.resolve->outputSize();
  }
  // Last frame's targets for the next resolve (nothing when no pass reads them).
  s.prev.capture(cmd, s.targets);
  output = &s.post.afterResolve(view, *output, outSize);
  // The reference is only ever read back with the frame's images; rendering it for other
  // frames would cost reference.samples scene renders each for nothing.
  std::shared_ptr<const Image> cachedReference;
  ReferenceCache::Claim referenceClaim;  // released when the frame ends, fulfilled or not
  if (s.reference && readImages) {
    for (int eye = 0; eye < eyes; ++eye)
      s.reference->prepare(eyeFrameState(state, eye, eyes, s.spec.tscmaa.eye_separation), shadows,
                           eye);
    if (s.options.referenceCache && !s.options.referenceKey.empty()) {
      auto lookup = s.options.referenceCache->findOrClaim(
          s.reference->frameKey(s.options.referenceKey, draws, shadows));
      cachedReference = std::move(lookup.image);
      referenceClaim = std::move(lookup.claim);
    }
    if (!cachedReference) {
      s.timer.begin(cmd, "reference");
      for (int eye = 0; eye < eyes; ++eye)
        s.reference->record(cmd, draws, s.instances.handle(), eye);
      s.timer.end(cmd);
    }
  }
  // A debug view replaces the output (after the passes it would otherwise feed).
  if (vk::Image* v = s.resolve ? s.resolve->debugView() : nullptr) output = v;
  if (vk::Image* v = s.post.debugView()) output = v;
  if (s.debugChannels) {
    s.debugChannels->record(cmd, *output, s.debugChannelsOut, outSize);
    output = &s.debugChannelsOut;
  }
  const bool readOutput = readImages || s.options.hashEveryFrame;
  if (readOutput) {
    FrameSources src;
    src.output = output;
    src.outputSize = outSize;
    src.renderSize = state.renderSize;
    src.resolveInput = resolveInput;
    src.targets = &s.targets;
    src.reference = cachedReference ? nullptr : s.reference.get();
    if (readImages) {
      if (s.resolve) src.captures = s.resolve->captures();
      for (auto& c : s.post.captures()) src.captures.push_back(std::move(c));
    }
    s.readback.record(cmd, s.spec, s.options, src, readImages);
  }
  s.ctx.submitAndWait(cmd);

  FrameRecord record;
  record.frame = frame;
  record.renderSize = state.renderSize;
  record.cameraCut = state.cameraCut;
  record.historyReset = state.resetHistory;
  record.gpuMs = s.timer.read();
  if (s.resolve) record.stats = s.resolve->stats();
  for (auto& stat : s.post.stats()) record.stats.push_back(std::move(stat));
  if (readOutput) s.readback.finish(record);
  if (cachedReference) {
    record.reference = *cachedReference;
    record.hasReference = true;
  } else if (referenceClaim && record.hasReference) {
    referenceClaim.fulfil(record.reference);
  }
  return record;
}

void renderSequence(Renderer& renderer, const spec::CaseSpec& spec,
                    const std::function<void(FrameRecord&)>& sink,
                    const std::function<void(int)>& progress) {
  const auto& wanted = spec.output.frames;
  for (int f = 0; f < spec.script.frames; ++f) {
    if (progress) progress(f);
    FrameRecord record =
        renderer.renderFrame(f, std::binary_search(wanted.begin(), wanted.end(), f));
    sink(record);
  }
}

}  // namespace taa
