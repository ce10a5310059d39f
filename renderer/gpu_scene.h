// The scene's geometry and textures on the device, uploaded once per run.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

namespace vk {
class Context;
}

class GpuScene {
 public:
  GpuScene(vk::Context& ctx, const scene::Scene& scene);

  const scene::Scene& cpu() const { return scene_; }
  VkBuffer vertices() const { return vertices_.handle(); }
  VkBuffer indices() const { return indices_.handle(); }
  // The material's base-colour texture, or a 1x1 white texture when it has none.
  VkImageView textureView(int material) const;
  VkSampler sampler(int material) const;
  size_t textureBytes() const { return textureBytes_; }

 private:
  const scene::Scene& scene_;
  vk::Buffer vertices_;
  vk::Buffer indices_;
  std::vector<vk::Image> textures_;
  vk::Image white_;
  vk::Sampler repeat_;
  vk::Sampler clamp_;
  size_t textureBytes_ = 0;
};

}  // namespace taa
