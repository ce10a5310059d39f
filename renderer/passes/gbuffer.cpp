#include "passes/gbuffer.h"

#include <stdexcept>

#include "api/device_error.h"
#include "common/shared.h"
#include "passes/draw_faces.h"
#include "passes/shadow.h"
#include "spec/case_spec.h"
#include "vk/barrier.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

void applyShadingSettings(GBufferConfig& config, const spec::CaseSpec& spec, ShadowPass* shadow) {
  if (shadow) {
    config.shadowAtlas = &shadow->atlas();
    config.shadowSampler = shadow->sampler();
  }
  config.normalStrength = spec.material.normal_strength;
  config.lod0 = spec.render.lod0;
  config.lod0AlphaTest = spec.render.lod0_alpha_test;
}

namespace {

constexpr VkFormat kColor = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kDepth = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kVelocity = VK_FORMAT_R16G16_SFLOAT;
constexpr VkFormat kNormal = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kIds = VK_FORMAT_R32_UINT;
constexpr VkFormat kAlbedo = VK_FORMAT_R16G16B16A16_SFLOAT;

vk::Image target(vk::Context& ctx, const char* name, const GBufferConfig& c, VkFormat format,
                 VkImageUsageFlags usage) {
  vk::ImageDesc d;
  d.name = name;
  d.width = c.width;
  d.height = c.height;
  d.format = format;
  d.usage = usage | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  return vk::Image(ctx, d);
}

// A multisampled twin of a target: drawn into and resolved within the pass, never read
// by anything else, so it is an attachment only.
vk::Image msTwin(vk::Context& ctx, const char* name, const GBufferConfig& c, VkFormat format,
                 VkImageUsageFlags usage) {
  vk::ImageDesc d;
  d.name = std::string(name) + "_ms" + std::to_string(c.samples);
  d.width = c.width;
  d.height = c.height;
  d.format = format;
  d.usage = usage | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  d.samples = c.samples;
  return vk::Image(ctx, d);
}

std::string sampleCountList(VkSampleCountFlags counts) {
  std::string out;
  for (uint32_t n = 1; n <= 64; n *= 2)
    if (counts & n) out += (out.empty() ? "" : ", ") + std::to_string(n);
  return out;
}

// Attachment formats in GBUF_OUT_* order; UNDEFINED where the case has no target,
// so the fragment shader's write there is discarded.
std::vector<VkFormat> colorFormats(const GBufferConfig& c) {
  std::vector<VkFormat> f(GBUF_OUT_COUNT, VK_FORMAT_UNDEFINED);
  f[GBUF_OUT_COLOR] = kColor;
  if (c.velocity) f[GBUF_OUT_VELOCITY] = kVelocity;
  if (c.normal) f[GBUF_OUT_NORMAL] = kNormal;
  if (c.ids) f[GBUF_OUT_IDS] = kIds;
  if (c.deferred) f[GBUF_OUT_ALBEDO] = kAlbedo;
  return f;
}

// The fragment-shader variant declaring exactly the allocated outputs (and, for the
// scene's surfaces with lighting.shadows, the shadow atlas).
std::string variant(const char* shader, const GBufferConfig& c, bool shadowed = false) {
  const int mask = (c.velocity ? GBUF_OUTPUT_VELOCITY : 0) | (c.normal ? GBUF_OUTPUT_NORMAL : 0) |
                   (c.ids ? GBUF_OUTPUT_IDS : 0) | (c.deferred ? GBUF_OUTPUT_ALBEDO : 0) |
                   (shadowed ? GBUF_OUTPUT_SHADOW : 0);
  return std::string(shader) + "." + std::to_string(mask);
}

}  // namespace

void checkSampleCount(vk::Context& ctx, const GBufferConfig& c) {
  if (c.samples <= 1) return;
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(ctx.physical(), &props);
  VkSampleCountFlags offered =
      props.limits.framebufferColorSampleCounts & props.limits.framebufferDepthSampleCounts;
  // The limits are a floor; each format the pass multisamples may offer fewer.
  struct Probe {
    bool used;
    VkFormat format;
    VkImageUsageFlags usage;
  };
  const VkImageUsageFlags transient = VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  const VkImageUsageFlags colorUse = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | transient;
  const Probe probes[] = {{true, kColor, colorUse},
                          {true, kDepth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | transient},
                          {c.velocity, kVelocity, colorUse},
                          {c.normal, kNormal, colorUse},
                          {c.ids, kIds, colorUse}};
  for (const Probe& p : probes) {
    if (!p.used) continue;
    VkImageFormatProperties f{};
    if (vkGetPhysicalDeviceImageFormatProperties(ctx.physical(), p.format, VK_IMAGE_TYPE_2D,
                                                 VK_IMAGE_TILING_OPTIMAL, p.usage, 0,
                                                 &f) != VK_SUCCESS)
      f.sampleCounts = VK_SAMPLE_COUNT_1_BIT;
    offered &= f.sampleCounts;
  }
  if (offered & c.samples) return;
  throw UnsupportedSettingError("render.msaa: " + std::to_string(c.samples) +
                                " samples per pixel are not offered by " + ctx.info().name +
                                " for the G-buffer's targets (it offers " +
                                sampleCountList(offered) + "); set render.msaa to one of those");
}

GBufferTargets::GBufferTargets(vk::Context& ctx, const GBufferConfig& c) {
  color = target(ctx, "color", c, kColor,
                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT);
  depth = target(ctx, "depth", c, kDepth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  if (c.velocity)
    velocity = target(ctx, "velocity", c, kVelocity, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  if (c.normal) normal = target(ctx, "normal", c, kNormal, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  if (c.ids) ids = target(ctx, "ids", c, kIds, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  if (c.deferred) albedo = target(ctx, "albedo", c, kAlbedo, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  if (c.samples <= 1) return;
  if (c.deferred)
    throw std::logic_error(
        "gbuffer: MSAA with the deferred path (validation refuses render.msaa there)");
  checkSampleCount(ctx, c);
  const VkImageUsageFlags colorUse = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  msColor = msTwin(ctx, "color", c, kColor, colorUse);
  msDepth = msTwin(ctx, "depth", c, kDepth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  if (c.velocity) msVelocity = msTwin(ctx, "velocity", c, kVelocity, colorUse);
  if (c.normal) msNormal = msTwin(ctx, "normal", c, kNormal, colorUse);
  if (c.ids) msIds = msTwin(ctx, "ids", c, kIds, colorUse);
}

std::vector<std::string> GBufferTargets::describe() const {
  std::vector<std::string> out;
  for (const vk::Image* i : {&color, &depth, &velocity, &normal, &ids, &albedo, &msColor, &msDepth,
                             &msVelocity, &msNormal, &msIds})
    if (*i)
      out.push_back(i->desc().name + " " + std::to_string(i->desc().width) + "x" +
                    std::to_string(i->desc().height) + " (" + std::to_string(i->bytes() / 1024) +
                    " KiB)");
  return out;
}

GBufferPass::GBufferPass(vk::Context& ctx, const GpuScene& scene, const GBufferConfig& config)
    : ctx_(ctx),
      scene_(scene),
      config_(config),
      pointClamp_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  vk::GraphicsDesc d;
  d.vertexShader = "gbuffer.vert";
  d.fragmentShader = variant("gbuffer.frag", config, config.shadowAtlas != nullptr);
  d.spec.set(GBUF_SPEC_DEFERRED, config.deferred)
      .set(GBUF_SPEC_LOD0, config.lod0)
      .set(GBUF_SPEC_LOD0_ALPHA, config.lod0AlphaTest);
  d.colorFormats = colorFormats(config);
  d.depthFormat = kDepth;
  // Per draw (DrawFaces): single-sided materials lose their back faces, double-sided ones
  // (foliage cards, glTF doubleSided) keep them and the shader flips their normals.
  d.dynamicFaces = true;
  d.samples = config.samples;
  opaque_ = vk::createGraphicsPipeline(ctx, "gbuffer", d);

  // Blended surfaces are shaded forward even on the deferred path (after lighting),
  // test depth without writing it, and leave the other targets alone.
  vk::GraphicsDesc b = d;
  b.spec = vk::SpecConstants()
               .set(GBUF_SPEC_DEFERRED, false)
               .set(GBUF_SPEC_LOD0, config.lod0)
               .set(GBUF_SPEC_LOD0_ALPHA, config.lod0AlphaTest);
  b.depthWrite = false;
  b.blendFirstAttachment = true;
  blended_ = vk::createGraphicsPipeline(ctx, "gbuffer_blend", b);

  vk::GraphicsDesc s = d;
  s.vertexShader = "sky.vert";
  s.fragmentShader = variant("sky.frag", config);
  s.vertexInput = false;
  s.dynamicFaces = false;
  s.cullMode = VK_CULL_MODE_NONE;  // one full-screen triangle
  s.depthWrite = false;
  s.depthCompare = VK_COMPARE_OP_EQUAL;  // only where no geometry moved depth off the far plane
  sky_ = vk::createGraphicsPipeline(ctx, "sky", s);

  if (config.deferred)
    lighting_ = vk::createComputePipeline(
        ctx, config.shadowAtlas ? "deferred_lighting.comp." + std::to_string(GBUF_OUTPUT_SHADOW)
                                : std::string("deferred_lighting.comp"));
}

void GBufferPass::drawList(VkCommandBuffer cmd, const vk::Pipeline& pipeline,
                           const std::vector<Draw>& draws, const Frame& f, float lodBias) {
  if (draws.empty()) return;
  pipeline.bind(cmd);
  const VkDeviceSize offset = 0;
  // Deformed draws read this frame's deformed vertices; the rest the scene's own.
  const VkBuffer buffers[2] = {scene_.vertices(), scene_.deformedVertices()};
  int boundBuffer = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &buffers[0], &offset);
  vkCmdBindIndexBuffer(cmd, scene_.indices(), 0, VK_INDEX_TYPE_UINT32);
  const auto& cpu = scene_.cpu();
  int boundMaterial = -1;
  DrawFaces faces;
  for (const auto& draw : draws) {
    const auto& prim = cpu.meshes[draw.mesh].primitives[draw.primitive];
    const auto& material = cpu.materials[prim.material];
    faces.apply(cmd, material.doubleSided, draw.mirrored);
    const int buffer = draw.deformedVertex >= 0 ? 1 : 0;
    if (buffer != boundBuffer) {
      vkCmdBindVertexBuffers(cmd, 0, 1, &buffers[buffer], &offset);
      boundBuffer = buffer;
    }
    if (prim.material != boundMaterial) {
      vk::Bindings b;
      b.uniform(GBUF_BINDING_FRAME, f.uniforms, f.offset, sizeof(gpu::FrameUniforms))
          .storageBuffer(GBUF_BINDING_INSTANCES, f.instances, 0, VK_WHOLE_SIZE)
          .sampled(GBUF_BINDING_TEXTURE, scene_.textureView(prim.material),
                   scene_.sampler(prim.material))
          .storageBuffer(GBUF_BINDING_PREV_POSITIONS, scene_.deformedPrevPositions(), 0,
                         VK_WHOLE_SIZE)
          .sampled(GBUF_BINDING_NORMAL_MAP, scene_.normalView(prim.material),
                   scene_.normalSampler(prim.material))
          .sampled(GBUF_BINDING_EMISSIVE_MAP, scene_.mapView(material.emissiveTexture),
                   scene_.mapSampler(material.emissiveTexture))
          .sampled(GBUF_BINDING_OCCLUSION_MAP, scene_.mapView(material.occlusionTexture),
                   scene_.mapSampler(material.occlusionTexture));
      if (config_.shadowAtlas)
        b.sampled(GBUF_BINDING_SHADOW, config_.shadowAtlas->view(), config_.shadowSampler);
      b.push(ctx_, cmd, pipeline);
      boundMaterial = prim.material;
    }
    gpu::DrawPush push{};
    push.material = uint32_t(prim.material);
    push.alphaCutoff = material.alphaMode == scene::AlphaMode::Mask ? material.alphaCutoff : -1.0f;
    push.lodBias = lodBias;
    push.baseColor = material.baseColorFactor;
    push.emissive = glm::vec4(material.emissive, material.normalTexture >= 0
                                                     ? config_.normalStrength * material.normalScale
                                                     : 0.0f);
    push.maps = materialMaps(material);
    push.occlusionStrength = material.occlusionStrength;
    pipeline.pushConstants(cmd, &push, sizeof(push));
    vkCmdDrawIndexed(cmd, prim.indexCount, draw.instanceCount, prim.firstIndex,
                     draw.deformedVertex >= 0 ? draw.deformedVertex : prim.vertexOffset,
                     draw.instance);
  }
}

void GBufferPass::record(VkCommandBuffer cmd, GBufferTargets& t, const DrawList& draws,
                         VkBuffer frameUniforms, VkDeviceSize uniformOffset, VkBuffer instances,
                         glm::ivec2 size, float lodBias) {
  const Frame f{frameUniforms, uniformOffset, instances};
  vk::Image* outputs[GBUF_OUT_COUNT] = {&t.color, &t.velocity, &t.normal, &t.ids, &t.albedo};
  // With MSAA the pass draws into the twins and resolves into the outputs; the twins' samples
  // are not kept (DONT_CARE), only the resolve is. No albedo twin: MSAA is forward only.
  const bool ms = config_.samples > 1;
  vk::Image* drawn[GBUF_OUT_COUNT] = {&t.msColor, &t.msVelocity, &t.msNormal, &t.msIds, &t.albedo};
  VkRenderingAttachmentInfo color[GBUF_OUT_COUNT];
  vk::BarrierBatch barriers;
  for (int i = 0; i < GBUF_OUT_COUNT; ++i) {
    color[i] = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    if (!*outputs[i]) continue;  // imageView stays VK_NULL_HANDLE: writes are discarded
    vk::Image& draw = ms ? *drawn[i] : *outputs[i];
    barriers.use(draw, vk::Use::ColorAttachment);
    color[i].imageView = draw.view();
    color[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color[i].storeOp = ms ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    if (!ms) continue;
    barriers.use(*outputs[i], vk::Use::ColorAttachment);
    // Integer ids cannot be averaged (a blend of two ids names neither object): sample 0.
    color[i].resolveMode =
        i == GBUF_OUT_IDS ? VK_RESOLVE_MODE_SAMPLE_ZERO_BIT : VK_RESOLVE_MODE_AVERAGE_BIT;
    color[i].resolveImageView = outputs[i]->view();
    color[i].resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  }
  color[GBUF_OUT_IDS].clearValue.color.uint32[0] = 0xffffffffu;
  if (config_.shadowAtlas) barriers.use(*config_.shadowAtlas, vk::Use::SampledGraphics);
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = ms ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {0.0f, 0};  // reversed Z: 0 is the far plane
  if (ms) {
    // Sample 0, not an average: an averaged depth at a silhouette lies on neither surface,
    // and reprojection and depth culling would then find a point in empty space.
    barriers.use(t.msDepth, vk::Use::DepthAttachment).use(t.depth, vk::Use::DepthResolve);
    depth.imageView = t.msDepth.view();
    depth.resolveMode = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;
    depth.resolveImageView = t.depth.view();
    depth.resolveImageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  } else {
    barriers.use(t.depth, vk::Use::DepthAttachment);
    depth.imageView = t.depth.view();
  }
  barriers.flush(cmd);

  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, {uint32_t(size.x), uint32_t(size.y)}};
  info.layerCount = 1;
  info.colorAttachmentCount = GBUF_OUT_COUNT;
  info.pColorAttachments = color;
  info.pDepthAttachment = &depth;
  const VkViewport viewport{0.0f, 0.0f, float(size.x), float(size.y), 0.0f, 1.0f};
  const VkRect2D scissor = info.renderArea;

  vkCmdBeginRendering(cmd, &info);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  drawList(cmd, opaque_, draws.opaque, f, lodBias);
  sky_.bind(cmd);
  // The sky reads the frame and the instance block's layout, no texture or vertices.
  vk::Bindings()
      .uniform(GBUF_BINDING_FRAME, f.uniforms, f.offset, sizeof(gpu::FrameUniforms))
      .storageBuffer(GBUF_BINDING_INSTANCES, f.instances, 0, VK_WHOLE_SIZE)
      .push(ctx_, cmd, sky_);
  // Its shaders share the draw block's declaration: it gets its own values (no instance,
  // material or alpha test) rather than whatever the last opaque draw pushed, or nothing
  // at all when the frame has no opaque draw.
  if (sky_.interface().pushConstantBytes >= sizeof(gpu::DrawPush)) {
    gpu::DrawPush sky{};
    sky.alphaCutoff = -1.0f;
    sky.lodBias = lodBias;
    sky_.pushConstants(cmd, &sky, sizeof(sky));
  }
  vkCmdDraw(cmd, 3, 1, 0, 0);
  if (config_.deferred) {
    vkCmdEndRendering(cmd);
    lightDeferred(cmd, t, f, size);
    barriers.use(t.depth, vk::Use::DepthAttachment);
    if (config_.shadowAtlas) barriers.use(*config_.shadowAtlas, vk::Use::SampledGraphics);
    for (int i = 0; i < GBUF_OUT_COUNT; ++i) {
      color[i].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
      if (*outputs[i]) barriers.use(*outputs[i], vk::Use::ColorAttachment);
    }
    barriers.flush(cmd);
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    vkCmdBeginRendering(cmd, &info);
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
  }
  drawList(cmd, blended_, draws.blended, f, lodBias);
  vkCmdEndRendering(cmd);
}

void GBufferPass::lightDeferred(VkCommandBuffer cmd, GBufferTargets& t, const Frame& f,
                                glm::ivec2 size) {
  vk::Dispatch d(lighting_);
  d.uniform(0, f.uniforms, f.offset, sizeof(gpu::FrameUniforms))
      .sample(1, t.albedo, pointClamp_.handle())
      .sample(2, t.normal, pointClamp_.handle())
      .sample(3, t.depth, pointClamp_.handle())
      .store(4, t.color);
  if (config_.shadowAtlas)
    d.sample(DEFERRED_BINDING_SHADOW, *config_.shadowAtlas, config_.shadowSampler);
  d.record(ctx_, cmd, uint32_t(size.x), uint32_t(size.y));
}

}  // namespace taa
