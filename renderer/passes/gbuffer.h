// The raster pass: scene geometry then sky into colour, depth and whichever
// auxiliary targets the case needs (velocity, normal, ids, albedo). With MSAA it
// draws into multisampled twins of the targets and resolves them at the end of the
// pass, so every later pass reads single-sample images as before.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "frame/draw_list.h"
#include "frame/gpu_scene.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

struct GBufferConfig {
  uint32_t width = 1;  // the largest render size of the run; frames may use less
  uint32_t height = 1;
  bool velocity = false;
  bool normal = false;
  bool ids = false;
  bool deferred = false;  // albedo target + deferred lighting pass
  uint32_t samples = 1;   // render.msaa; forward only (validation refuses it with deferred)
  // lighting.shadows: shading samples this atlas (renderer/passes/shadow.h) through
  // `shadowSampler`.
  vk::Image* shadowAtlas = nullptr;
  VkSampler shadowSampler = VK_NULL_HANDLE;
  float normalStrength = 1.0f;  // material.normal_strength
  bool lod0 = false;            // render.lod0
  bool lod0AlphaTest = false;   // render.lod0_alpha_test
};

namespace spec {
struct CaseSpec;
}
class ShadowPass;

// The case's shading settings on a G-buffer configuration: the shadow atlas (when `shadow`),
// normal-map strength and the LOD choices. The frame's raster and the reference's must shade
// alike, so both take them from here.
void applyShadingSettings(GBufferConfig& config, const spec::CaseSpec& spec, ShadowPass* shadow);

// Throws UnsupportedSettingError naming render.msaa and the counts the device offers
// when `config.samples` is not one of them for every target the pass would multisample.
void checkSampleCount(vk::Context& ctx, const GBufferConfig& config);

struct GBufferTargets {
  vk::Image color;     // RGBA16F, linear HDR
  vk::Image depth;     // D32, reversed Z (1 near, 0 far)
  vk::Image velocity;  // RG16F, pixels, un-jittered
  vk::Image normal;    // RGBA16F, world-space normal in xyz
  vk::Image ids;       // R32_UINT, object id << 16 | material id; sky = 0xffffffff
  vk::Image albedo;    // RGBA16F, deferred only; alpha 0 marks sky
  // MSAA only: what the pass draws into. Colour, velocity and normal resolve by averaging
  // (the only resolve Vulkan has for float formats), depth and ids take sample 0.
  vk::Image msColor, msDepth, msVelocity, msNormal, msIds;

  GBufferTargets(vk::Context& ctx, const GBufferConfig& config);
  // Every allocated target as "name WxH format", for the run log.
  std::vector<std::string> describe() const;
};

class GBufferPass {
 public:
  GBufferPass(vk::Context& ctx, const GpuScene& scene, const GBufferConfig& config);

  // Records the pass into `cmd` for a frame rendered at `size` (top-left of the targets)
  // with the FrameUniforms found at `frameUniforms` + `uniformOffset`.
  void record(VkCommandBuffer cmd, GBufferTargets& targets, const DrawList& draws,
              VkBuffer frameUniforms, VkDeviceSize uniformOffset, VkBuffer instances,
              glm::ivec2 size, float lodBias);

 private:
  struct Frame {
    VkBuffer uniforms;
    VkDeviceSize offset;
    VkBuffer instances;
  };
  void drawList(VkCommandBuffer cmd, const vk::Pipeline& pipeline, const std::vector<Draw>& draws,
                const Frame& f, float lodBias);
  void lightDeferred(VkCommandBuffer cmd, GBufferTargets& targets, const Frame& f, glm::ivec2 size);

  vk::Context& ctx_;
  const GpuScene& scene_;
  GBufferConfig config_;
  vk::Pipeline opaque_;
  vk::Pipeline blended_;
  vk::Pipeline sky_;
  vk::Pipeline lighting_;  // deferred only
  vk::Sampler pointClamp_;
};

}  // namespace taa
