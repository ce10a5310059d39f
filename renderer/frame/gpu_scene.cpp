#include "frame/gpu_scene.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "frame/draw_list.h"
#include "vk/context.h"
#include "vk/transfer.h"

namespace taa {

namespace {
// More levels than any texture can have: the sampler must not cap the mip chain.
constexpr float kMaxLod = 16.0f;
}  // namespace

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
      deformedCapacity_(deformedVertexCount(scene)),
      repeat_(ctx, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, kMaxLod, true),
      clamp_(ctx, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, kMaxLod, true) {
  for (const auto& t : scene.textures) {
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

VkImageView GpuScene::textureView(int material) const {
  const int t = scene_.materials[material].baseColorTexture;
  return t >= 0 ? textures_[t].view() : white_.view();
}

VkImageView GpuScene::normalView(int material) const {
  const int t = scene_.materials[material].normalTexture;
  return t >= 0 ? textures_[t].view() : white_.view();
}

VkSampler GpuScene::normalSampler(int material) const {
  const int t = scene_.materials[material].normalTexture;
  return (t < 0 || scene_.textures[t].repeat) ? repeat_.handle() : clamp_.handle();
}

VkSampler GpuScene::sampler(int material) const {
  const int t = scene_.materials[material].baseColorTexture;
  return (t < 0 || scene_.textures[t].repeat) ? repeat_.handle() : clamp_.handle();
}

}  // namespace taa
