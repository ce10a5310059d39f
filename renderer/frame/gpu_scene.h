// The scene's geometry and textures on the device, uploaded once per run.
#pragma once

#include <map>
#include <vector>

#include "scene/scene.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// The MATERIAL_* bits (shaders/common/shared.h) of a material: which textures beyond the
// base colour its draws and traced hits sample, from which UV set, and whether it is unlit.
uint32_t materialMaps(const scene::Material& m);

namespace vk {
class Context;
}

class GpuScene {
 public:
  GpuScene(vk::Context& ctx, const scene::Scene& scene);

  const scene::Scene& cpu() const { return scene_; }
  VkBuffer vertices() const { return vertices_.handle(); }
  VkBuffer indices() const { return indices_.handle(); }
  // This frame's skinned and morphed vertices (DrawList::deformed) and their previous
  // positions, rewritten by uploadDeformed every frame; at least one element each so
  // they can always be bound.
  VkBuffer deformedVertices() const { return deformed_.handle(); }
  VkBuffer deformedPrevPositions() const { return deformedPrev_.handle(); }
  void uploadDeformed(const std::vector<scene::Vertex>& vertices,
                      const std::vector<glm::vec4>& prevPositions);
  // The material's base-colour texture, or a 1x1 white texture when it has none.
  VkImageView textureView(int material) const;
  VkSampler sampler(int material) const;
  // The material's normal map (white, never read, when it has none) and its sampler.
  VkImageView normalView(int material) const;
  VkSampler normalSampler(int material) const;
  // Any scene texture by index (-1: the 1x1 white texture) and its sampler.
  VkImageView mapView(int texture) const;
  VkSampler mapSampler(int texture) const;
  size_t textureBytes() const { return textureBytes_; }

 private:
  const scene::Scene& scene_;
  vk::Buffer vertices_;
  vk::Buffer indices_;
  vk::Buffer deformed_;
  vk::Buffer deformedPrev_;
  size_t deformedCapacity_ = 0;
  std::vector<vk::Image> textures_;
  vk::Image white_;
  // One sampler per distinct TextureSampler::key() the textures use, and the default.
  std::map<int, vk::Sampler> samplers_;
  size_t textureBytes_ = 0;
};

}  // namespace taa
