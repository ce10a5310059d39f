#include "frame/gpu_scene.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "common/shared.h"
#include "frame/draw_list.h"
#include "vk/context.h"
#include "vk/transfer.h"

namespace taa {

namespace {
// More levels than any texture can have: the sampler must not cap the mip chain.
constexpr float kMaxLod = 16.0f;

VkSamplerAddressMode addressMode(scene::Wrap w) {
  switch (w) {
    case scene::Wrap::ClampToEdge:
      return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case scene::Wrap::MirroredRepeat:
      return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case scene::Wrap::Repeat:
      break;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkFilter filter(scene::Filter f) {
  return f == scene::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
}

// glTF's sampler as Vulkan's: wrapS is u, wrapT is v. A minFilter without mipmaps samples
// level 0 alone: maxLod 0.25 with nearest mip selection rounds every footprint to level 0,
// while a minified lookup still gets minFilter (Vulkan picks magFilter for a level of detail
// at or below 0, so maxLod 0 would magnify everything).
VkSamplerCreateInfo samplerInfo(const scene::TextureSampler& s) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter(s.mag);
  info.minFilter = filter(s.min);
  info.mipmapMode = s.mip == scene::MipFilter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR
                                                      : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = addressMode(s.wrapS);
  info.addressModeV = addressMode(s.wrapT);
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.maxLod = s.mip == scene::MipFilter::None ? 0.25f : kMaxLod;
  return info;
}
}  // namespace

uint32_t materialMaps(const scene::Material& m) {
  uint32_t bits = 0;
  if (m.baseColorTexture >= 0 && m.baseColorUv == 1) bits |= MATERIAL_BASE_UV1;
  if (m.normalTexture >= 0 && m.normalUv == 1) bits |= MATERIAL_NORMAL_UV1;
  if (m.emissiveTexture >= 0) bits |= MATERIAL_EMISSIVE_MAP | (m.emissiveUv == 1 ? MATERIAL_EMISSIVE_UV1 : 0u);
  if (m.occlusionTexture >= 0)
    bits |= MATERIAL_OCCLUSION_MAP | (m.occlusionUv == 1 ? MATERIAL_OCCLUSION_UV1 : 0u);
  if (m.unlit) bits |= MATERIAL_UNLIT;
  return bits;
}

GpuScene::GpuScene(vk::Context& ctx, const scene::Scene& scene)
    : scene_(scene),
      vertices_(vk::uploadBuffer(ctx, scene.vertices.data(), scene.vertices.size() * sizeof(scene::Vertex),
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT)),
      indices_(vk::uploadBuffer(ctx, scene.indices.data(), scene.indices.size() * sizeof(uint32_t),
                                VK_BUFFER_USAGE_INDEX_BUFFER_BIT)),
      deformed_(ctx, std::max<size_t>(1, deformedVertexCount(scene)) * sizeof(scene::Vertex),
                VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, true),
      deformedPrev_(ctx, std::max<size_t>(1, deformedVertexCount(scene)) * sizeof(glm::vec4),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true),
      deformedCapacity_(deformedVertexCount(scene)) {
  samplers_.emplace(scene::TextureSampler{}.key(), vk::Sampler(ctx, samplerInfo({})));
  for (const auto& t : scene.textures) {
    if (!samplers_.count(t.sampler.key()))
      samplers_.emplace(t.sampler.key(), vk::Sampler(ctx, samplerInfo(t.sampler)));
    vk::ImageDesc d;
    d.name = "texture";
    d.width = uint32_t(t.levels[0].width);
    d.height = uint32_t(t.levels[0].height);
    d.mipLevels = uint32_t(t.levels.size());
    d.format = t.linear ? VK_FORMAT_R8G8B8A8_UNORM : VK_FORMAT_R8G8B8A8_SRGB;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    vk::Image image(ctx, d);
    std::vector<const void*> levels;
    for (const auto& l : t.levels) {
      levels.push_back(l.rgba.data());
      textureBytes_ += l.rgba.size();
    }
    vk::uploadImage(ctx, image, levels);
    textures_.push_back(std::move(image));
  }
  vk::ImageDesc d;
  d.name = "white";
  d.format = VK_FORMAT_R8G8B8A8_SRGB;
  d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  white_ = vk::Image(ctx, d);
  const uint8_t texel[4] = {255, 255, 255, 255};
  vk::uploadImage(ctx, white_, {texel});
}

void GpuScene::uploadDeformed(const std::vector<scene::Vertex>& vertices,
                              const std::vector<glm::vec4>& prevPositions) {
  if (vertices.size() > deformedCapacity_ || prevPositions.size() != vertices.size())
    throw std::logic_error("GpuScene: the deformed vertex count changed between frames");
  if (vertices.empty()) return;
  std::memcpy(deformed_.mapped(), vertices.data(), vertices.size() * sizeof(scene::Vertex));
  std::memcpy(deformedPrev_.mapped(), prevPositions.data(), prevPositions.size() * sizeof(glm::vec4));
}

VkImageView GpuScene::mapView(int texture) const {
  return texture >= 0 ? textures_[size_t(texture)].view() : white_.view();
}

VkSampler GpuScene::mapSampler(int texture) const {
  const int key = texture >= 0 ? scene_.textures[size_t(texture)].sampler.key()
                               : scene::TextureSampler{}.key();
  return samplers_.at(key).handle();
}

VkImageView GpuScene::textureView(int material) const {
  return mapView(scene_.materials[size_t(material)].baseColorTexture);
}

VkSampler GpuScene::sampler(int material) const {
  return mapSampler(scene_.materials[size_t(material)].baseColorTexture);
}

VkImageView GpuScene::normalView(int material) const {
  return mapView(scene_.materials[size_t(material)].normalTexture);
}

VkSampler GpuScene::normalSampler(int material) const {
  return mapSampler(scene_.materials[size_t(material)].normalTexture);
}

}  // namespace taa
