#include "passes/reference.h"

#include <cmath>
#include <cstring>

#include "core/sha256.h"
#include "frame/frame_uniforms.h"
#include "script/jitter.h"
#include "script/stereo.h"
#include "vk/context.h"
#include "vk/dispatch.h"
#include "vk/pipeline.h"

namespace taa {

namespace {

GBufferConfig referenceConfig(const spec::CaseSpec& spec, ShadowPass* shadow) {
  GBufferConfig c;
  applyShadingSettings(c, spec, shadow);
  c.width = uint32_t(spec.render.width);
  c.height = uint32_t(spec.render.height);
  c.deferred = spec.render.path == spec::RenderPath::Deferred;
  c.normal = c.deferred;
  return c;
}

double radicalInverse2(uint32_t i) {
  double r = 0.0, f = 0.5;
  for (; i; i >>= 1, f *= 0.5)
    if (i & 1u) r += f;
  return r;
}

struct AccumulatePush {
  int32_t width, height;
  uint32_t mode;
  float invCount;
  int32_t offsetX;  // of the eye's half in the accumulator
};

}  // namespace

std::vector<glm::vec2> referenceOffsets(int count) {
  std::vector<glm::vec2> out;
  const int m = int(std::lround(std::sqrt(double(count))));
  if (m * m == count) {
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        out.emplace_back((i + 0.5f) / float(m) - 0.5f, (j + 0.5f) / float(m) - 0.5f);
  } else {
    for (int i = 0; i < count; ++i)
      out.emplace_back(float((i + 0.5) / count - 0.5),
                       float(radicalInverse2(uint32_t(i)) + 0.5 / count - 0.5));
  }
  return out;
}

ReferencePass::ReferencePass(vk::Context& ctx, const spec::CaseSpec& spec, const GpuScene& scene,
                             ShadowPass* shadow, StillImagePass* still)
    : ctx_(ctx),
      spec_(spec),
      offsets_(referenceOffsets(spec.reference.samples)),
      config_(referenceConfig(spec, shadow)),
      targets_(ctx, config_),
      gbuffer_(ctx, scene, config_),
      accumulate_(vk::createComputePipeline(ctx, "reference_accumulate.comp")),
      point_(ctx, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE),
      still_(still) {
  vk::ImageDesc d;
  d.name = "reference";
  d.width = config_.width * uint32_t(eyeCount(spec));
  d.height = config_.height;
  d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
  d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  accum_ = vk::Image(ctx, d);
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(ctx.physical(), &props);
  const VkDeviceSize align = props.limits.minUniformBufferOffsetAlignment;
  stride_ = (sizeof(gpu::FrameUniforms) + align - 1) / align * align;
  uniforms_ = vk::Buffer(ctx, stride_ * offsets_.size() * size_t(eyeCount(spec)),
                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
}

void ReferencePass::setShaders(const std::vector<std::string>& names) {
  shaderNames_ = names;
  Sha256 h;
  for (const auto& name : names) {
    const std::vector<uint32_t> words = vk::loadSpirv(name);
    const uint64_t n[2] = {name.size(), words.size()};
    h.update(n, sizeof(n));  // lengths delimit the parts
    h.update(name.data(), name.size());
    h.update(words.data(), words.size() * sizeof(uint32_t));
  }
  const auto digest = h.finish();
  shaderDigest_ = toHex(digest.data(), digest.size());
}

void ReferencePass::prepare(const script::FrameState& state, const ShadowCascades& shadows,
                            int eye) {
  const glm::ivec2 size(spec_.render.width, spec_.render.height);
  // The same instant as the frame, without the frame's jitter and at output size.
  script::FrameState sub = state;
  sub.renderSize = size;
  const size_t first = size_t(eye) * offsets_.size();
  for (size_t i = 0; i < offsets_.size(); ++i) {
    sub.jitter = offsets_[i];
    sub.jitteredProjection = script::applyJitter(state.camera.projection, offsets_[i], size);
    gpu::FrameUniforms u = makeFrameUniforms(sub, spec_.lighting);
    setShadowUniforms(u, shadows);
    std::memcpy(static_cast<uint8_t*>(uniforms_.mapped()) + (first + i) * stride_, &u, sizeof(u));
  }
}

void ReferencePass::record(VkCommandBuffer cmd, const DrawList& draws, VkBuffer instances,
                           int eye) {
  const glm::ivec2 size(spec_.render.width, spec_.render.height);
  const size_t first = size_t(eye) * offsets_.size();
  for (size_t i = 0; i < offsets_.size(); ++i) {
    if (still_)
      still_->record(cmd, targets_.color, size, offsets_[i], true);
    else
      gbuffer_.record(cmd, targets_, draws, uniforms_.handle(), (first + i) * stride_, instances,
                      size, 0.0f);
    const uint32_t mode = (i > 0 ? 1u : 0u) | (i + 1 == offsets_.size() ? 2u : 0u);
    const AccumulatePush push{size.x, size.y, mode, 1.0f / float(offsets_.size()), eye * size.x};
    vk::Dispatch(accumulate_)
        .sample(0, targets_.color, point_.handle())
        .store(1, accum_)
        .constants(push)
        .record(ctx_, cmd, uint32_t(size.x), uint32_t(size.y));
  }
}

std::string ReferencePass::frameKey(const std::string& caseKey, const DrawList& draws,
                                    const ShadowCascades& shadows) const {
  Sha256 h;
  auto add = [&h](const void* data, size_t bytes) {
    const uint64_t n = bytes;
    h.update(&n, sizeof(n));  // lengths delimit the parts
    h.update(data, bytes);
  };
  add(caseKey.data(), caseKey.size());
  add(shaderDigest_.data(), shaderDigest_.size());
  const uint32_t shape[4] = {accum_.desc().width, accum_.desc().height, uint32_t(offsets_.size()),
                             still_ ? 1u : 0u};
  add(shape, sizeof(shape));
  const size_t eyes = size_t(eyeCount(spec_));
  for (size_t k = 0; k < eyes * offsets_.size(); ++k)
    add(static_cast<const uint8_t*>(uniforms_.mapped()) + k * stride_, sizeof(gpu::FrameUniforms));
  add(draws.instances.data(), draws.instances.size() * sizeof(gpu::InstanceData));
  // One instance each, as the draws were before they were instanced: the same scene keeps
  // the same key, and cached references stay valid.
  for (const auto* list : {&draws.opaque, &draws.blended}) {
    std::vector<int32_t> d;
    for (const Draw& x : singleInstanceDraws(*list))
      d.insert(d.end(), {int32_t(x.instance), x.mesh, x.primitive, x.deformedVertex});
    add(d.data(), d.size() * sizeof(int32_t));
  }
  add(draws.deformed.data(), draws.deformed.size() * sizeof(scene::Vertex));
  add(draws.deformedPrev.data(), draws.deformedPrev.size() * sizeof(glm::vec4));
  // The atlas the sub-samples read is drawn from these cascades and the same draws.
  add(&shadows.count, sizeof(shadows.count));
  add(shadows.splits.data(), sizeof(shadows.splits));
  add(shadows.lightViewProj.data(), sizeof(shadows.lightViewProj));
  add(shadows.texelWorld.data(), sizeof(shadows.texelWorld));
  add(&shadows.depthPerWorld, sizeof(shadows.depthPerWorld));
  add(&shadows.forward, sizeof(shadows.forward));
  add(&shadows.origin, sizeof(shadows.origin));
  const auto digest = h.finish();
  return toHex(digest.data(), digest.size());
}

}  // namespace taa
