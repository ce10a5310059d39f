#include "passes/adaptive/trace.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>

#include "passes/adaptive/trace_geometry.h"
#include "scene/trace_textures.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

namespace {

template <class T>
void write(vk::Buffer& buffer, size_t first, const std::vector<T>& items) {
  if (!items.empty())
    std::memcpy(static_cast<T*>(buffer.mapped()) + first, items.data(), items.size() * sizeof(T));
}

// A host-visible storage buffer of at least one element (empty scenes bind it too).
template <class T>
vk::Buffer storage(vk::Context& ctx, size_t count) {
  return vk::Buffer(ctx, std::max<size_t>(count, 1) * sizeof(T), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    true);
}

size_t countMoverTriangles(const scene::Scene& scene, const DrawList& draws) {
  std::vector<scene::Triangle> tris;
  collectTriangles(scene, draws, true, tris, nullptr, nullptr);
  return tris.size();
}

}  // namespace

std::vector<glm::vec2> traceOffsets(int samples) {
  std::vector<glm::vec2> out;
  for (int i = 0; i < samples; ++i) {
    double r = 0.0, f = 0.5;  // base-2 radical inverse of i
    for (auto k = uint32_t(i); k; k >>= 1, f *= 0.5)
      if (k & 1u) r += f;
    out.emplace_back(float((i + 0.5) / samples - 0.5), float(r + 0.5 / samples - 0.5));
  }
  return out;
}

gpu::TraceUniforms makeTraceUniforms(const spec::CaseSpec& spec, const script::FrameState& state,
                                     float lodBias, uint32_t staticRoot, uint32_t moverRoot) {
  gpu::TraceUniforms u{};
  const glm::vec2 size(state.renderSize);
  u.size = glm::vec4(size, 1.0f / size);
  u.params = glm::vec4(std::exp2(lodBias), 0.0f, 0.0f, 0.0f);
  u.roots = glm::uvec4(staticRoot, moverRoot, 0u, 0u);
  const auto offsets = traceOffsets(spec.adaptive.samples);
  for (size_t i = 0; i < offsets.size() && i < TRACE_MAX_SAMPLES; ++i)
    u.offsets[i] = glm::vec4(offsets[i], 0, 0);
  return u;
}

TracePass::TracePass(vk::Context& ctx, const spec::CaseSpec& spec, const GpuScene& scene,
                     const DrawList& firstFrame)
    : ctx_(ctx),
      spec_(spec),
      scene_(scene),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
  if (ctx.info().maxPushDescriptors < TRACE_BINDING_COUNT - 1 + TRACE_MAX_TEXTURES)
    throw vk::EnvironmentError(ctx.info().name +
                               " pushes too few descriptors for the adaptive tracer");
  // One texture slot per distinct texture the materials' traced maps use
  // (traceTextureSlots: the case loader refuses a scene with more than the shader has).
  const scene::Scene& cpu = scene.cpu();
  const scene::TraceTextureSlots slots = scene::traceTextureSlots(cpu);
  for (const int texture : slots.textures) {
    views_.push_back(scene.mapView(texture));
    samplers_.push_back(scene.mapSampler(texture));
  }
  if (views_.size() > TRACE_MAX_TEXTURES)
    throw std::logic_error("adaptive trace: more texture slots than the case check allows");
  // Every material has a base colour slot (the white texture when it has none), so a scene
  // with materials uses at least one; the shader compiles out the slots past these.
  textureSlots_ = uint32_t(std::max<size_t>(views_.size(), 1));
  std::vector<gpu::TraceMaterial> materials;
  for (size_t m = 0; m < cpu.materials.size(); ++m) {
    const scene::Material& src = cpu.materials[m];
    gpu::TraceMaterial t{};
    t.baseColor = src.baseColorFactor;
    t.alphaCutoff = src.alphaMode == scene::AlphaMode::Mask ? src.alphaCutoff : -1.0f;
    t.texture = uint32_t(slots.base[m]);
    t.blend = src.alphaMode == scene::AlphaMode::Blend ? 1u : 0u;
    t.doubleSided = src.doubleSided ? 1u : 0u;
    t.emissive = glm::vec4(src.emissive, src.occlusionStrength);
    t.maps = materialMaps(src);
    t.emissiveTexture = uint32_t(slots.emissive[m]);
    t.occlusionTexture = uint32_t(slots.occlusion[m]);
    materials.push_back(t);
  }
  // The array is declared full size: unused slots repeat the first texture.
  while (views_.size() < TRACE_MAX_TEXTURES) {
    views_.push_back(views_.empty() ? scene.textureView(0) : views_.front());
    samplers_.push_back(samplers_.empty() ? scene.sampler(0) : samplers_.front());
  }

  const TraceGeometry world = buildTraceGeometry(cpu, firstFrame, false, 0, 0);
  staticNodes_ = uint32_t(world.nodes.size());
  staticTriangles_ = uint32_t(world.triangles.size());
  moverTriangles_ = uint32_t(countMoverTriangles(cpu, firstFrame));
  const size_t triangles = size_t(staticTriangles_) + moverTriangles_;
  nodes_ = storage<gpu::BvhNode>(ctx, size_t(staticNodes_) + 2 * size_t(moverTriangles_));
  triangles_ = storage<gpu::TraceTriangle>(ctx, triangles);
  shading_ = storage<gpu::TraceShading>(ctx, triangles);
  materials_ = storage<gpu::TraceMaterial>(ctx, materials.size());
  uniforms_ = vk::Buffer(ctx, sizeof(gpu::TraceUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
  write(nodes_, 0, world.nodes);
  write(triangles_, 0, world.triangles);
  write(shading_, 0, world.shading);
  write(materials_, 0, materials);

  vk::SpecConstants c;
  // render.lod0 samples mip 0 everywhere, the tracer included.
  c.set(TRACE_SPEC_SAMPLES, spec.adaptive.samples)
      .set(TRACE_SPEC_RAY_LOD, spec.adaptive.ray_lod && !spec.render.lod0)
      .setFloat(TRACE_SPEC_ANISO, spec.adaptive.aniso)
      .set(TRACE_SPEC_LOD0_ALPHA, spec.render.lod0_alpha_test)
      .set(TRACE_SPEC_TEXTURE_SLOTS, textureSlots_);
  pipeline_ = vk::createComputePipeline(ctx, "adaptive_trace.comp", c);
}

std::string TracePass::describe() const {
  return "pass adaptive_trace: " + std::to_string(spec_.adaptive.samples) +
         " rays per marked pixel, " + std::to_string(staticTriangles_) + " static triangles (" +
         std::to_string(staticNodes_) + " BVH nodes), " + std::to_string(moverTriangles_) +
         " mover triangles rebuilt per frame, " + std::to_string(textureSlots_) +
         " texture slots, texture LOD " +
         (spec_.adaptive.ray_lod ? "from ray differentials" : "0") + "; buffers: BVH " +
         std::to_string(nodes_.size()) + " B, triangles " + std::to_string(triangles_.size()) +
         " B, shading " + std::to_string(shading_.size()) + " B, materials " +
         std::to_string(materials_.size()) + " B";
}

void TracePass::record(VkCommandBuffer cmd, const script::FrameState& state, const DrawList& draws,
                       VkBuffer frameUniforms, float lodBias, vk::Image& mask, vk::Image& target) {
  uint32_t moverRoot = TRACE_NO_ROOT;
  if (moverTriangles_ > 0) {
    const TraceGeometry movers =
        buildTraceGeometry(scene_.cpu(), draws, true, staticNodes_, staticTriangles_);
    if (movers.triangles.size() != moverTriangles_)
      throw std::logic_error("adaptive trace: the movers' triangle count changed between frames");
    write(nodes_, staticNodes_, movers.nodes);
    write(triangles_, staticTriangles_, movers.triangles);
    write(shading_, staticTriangles_, movers.shading);
    moverRoot = staticNodes_;
  }
  const uint32_t staticRoot = staticTriangles_ > 0 ? 0u : TRACE_NO_ROOT;
  const gpu::TraceUniforms u = makeTraceUniforms(spec_, state, lodBias, staticRoot, moverRoot);
  std::memcpy(uniforms_.mapped(), &u, sizeof(u));

  vk::Dispatch(pipeline_)
      .uniform(TRACE_BINDING_FRAME, frameUniforms, 0, sizeof(gpu::FrameUniforms))
      .uniform(TRACE_BINDING_PARAMS, uniforms_.handle(), 0, sizeof(u))
      .storageBuffer(TRACE_BINDING_NODES, nodes_.handle())
      .storageBuffer(TRACE_BINDING_TRIANGLES, triangles_.handle())
      .storageBuffer(TRACE_BINDING_SHADING, shading_.handle())
      .storageBuffer(TRACE_BINDING_MATERIALS, materials_.handle())
      .sample(TRACE_BINDING_MASK, mask, point_.handle())
      .store(TRACE_BINDING_OUT, target)
      .sampledArray(TRACE_BINDING_TEXTURES, views_, samplers_)
      .record(ctx_, cmd, uint32_t(state.renderSize.x), uint32_t(state.renderSize.y));
}

}  // namespace taa
