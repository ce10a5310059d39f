// The shadow caster pass: the frame's opaque and alpha-tested draws, depth only, once per
// cascade into its tile of one atlas (lighting.shadows). Shading samples the atlas through
// a comparison sampler (common/shadow.glsl); blended surfaces receive shadows but cast none.
#pragma once

#include <string>
#include <vector>

#include "frame/draw_list.h"
#include "frame/gpu_scene.h"
#include "frame/shadow_cascades.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// World bounds of the draws that cast shadows (opaque and alpha-tested), from each mesh's
// bounds at rest under its instance's transform.
SceneBox casterBounds(const scene::Scene& scene, const DrawList& draws);

class ShadowPass {
 public:
  // `lod0Alpha`: alpha-tested casters test the alpha of mip 0 (render.lod0 or lod0_alpha_test).
  ShadowPass(vk::Context& ctx, const GpuScene& scene, int cascades, bool lod0Alpha);

  // Renders every cascade of `c` into the atlas, which is then ready to be sampled.
  void record(VkCommandBuffer cmd, const ShadowCascades& c, const DrawList& draws,
              VkBuffer instances);
  vk::Image& atlas() { return atlas_; }
  VkSampler sampler() const { return compare_.handle(); }
  std::string describe() const;

 private:
  vk::Context& ctx_;
  const GpuScene& scene_;
  int cascades_;
  vk::Image atlas_;  // D32, kShadowMapSize * cascades wide, kShadowMapSize high
  vk::Pipeline casters_;
  vk::Sampler compare_;
};

}  // namespace taa
