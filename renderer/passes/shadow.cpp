#include "passes/shadow.h"

#include <glm/vec4.hpp>

#include "common/shared.h"
#include "passes/draw_faces.h"
#include "vk/context.h"

namespace taa {

SceneBox casterBounds(const scene::Scene& scene, const DrawList& draws) {
  SceneBox box;
  for (const Draw& d : draws.opaque) {
    const scene::Mesh& mesh = scene.meshes[size_t(d.mesh)];
    for (uint32_t k = d.instance; k < d.instance + d.instanceCount; ++k) {
      const glm::mat4& model = draws.instances[k].model;
      for (int i = 0; i < 8; ++i) {
        const glm::vec4 corner((i & 1) ? mesh.boundsMax.x : mesh.boundsMin.x,
                               (i & 2) ? mesh.boundsMax.y : mesh.boundsMin.y,
                               (i & 4) ? mesh.boundsMax.z : mesh.boundsMin.z, 1.0f);
        box.add(glm::vec3(model * corner));
      }
    }
  }
  return box;
}

ShadowPass::ShadowPass(vk::Context& ctx, const GpuScene& scene, int cascades, bool lod0Alpha)
    : ctx_(ctx), scene_(scene), cascades_(cascades) {
  vk::ImageDesc d;
  d.name = "shadow_atlas";
  d.width = uint32_t(kShadowMapSize * cascades);
  d.height = uint32_t(kShadowMapSize);
  d.format = VK_FORMAT_D32_SFLOAT;
  d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  atlas_ = vk::Image(ctx, d);

  vk::GraphicsDesc g;
  g.vertexShader = "shadow_depth.vert";
  g.fragmentShader = "shadow_depth.frag";
  g.depthFormat = VK_FORMAT_D32_SFLOAT;
  g.depthCompare = VK_COMPARE_OP_LESS;  // 0 at the light's side of the scene
  // Per draw (DrawFaces), as the G-buffer: a single-sided surface casts only from its front
  // (towards the light), a double-sided one (cards) from both sides.
  g.dynamicFaces = true;
  g.spec.set(GBUF_SPEC_LOD0_ALPHA, lod0Alpha);
  casters_ = vk::createGraphicsPipeline(ctx, "shadow_casters", g);

  // Bilinear comparison: each tap is the lit share of a 2x2 texel footprint.
  VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  s.magFilter = s.minFilter = VK_FILTER_LINEAR;
  s.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  s.compareEnable = VK_TRUE;
  s.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;  // lit when the receiver is not behind the caster
  compare_ = vk::Sampler(ctx, s);
}

std::string ShadowPass::describe() const {
  return "pass shadow (" + std::to_string(cascades_) + " cascades, " +
         std::to_string(kShadowMapSize) + "x" + std::to_string(kShadowMapSize) +
         " D32 each, atlas " + std::to_string(atlas_.bytes() / 1024) + " KiB)";
}

void ShadowPass::record(VkCommandBuffer cmd, const ShadowCascades& c, const DrawList& draws,
                        VkBuffer instances) {
  atlas_.use(cmd, vk::Use::DepthAttachment);
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = atlas_.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {1.0f, 0};  // nothing casts: every receiver is lit
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, {atlas_.desc().width, atlas_.desc().height}};
  info.layerCount = 1;
  info.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &info);
  casters_.bind(cmd);
  const VkDeviceSize offset = 0;
  const VkBuffer buffers[2] = {scene_.vertices(), scene_.deformedVertices()};
  vkCmdBindIndexBuffer(cmd, scene_.indices(), 0, VK_INDEX_TYPE_UINT32);
  const auto& cpu = scene_.cpu();
  for (int i = 0; i < c.count; ++i) {
    const VkViewport viewport{float(i * kShadowMapSize), 0.0f, float(kShadowMapSize),
                              float(kShadowMapSize),     0.0f, 1.0f};
    const VkRect2D scissor{{i * kShadowMapSize, 0},
                           {uint32_t(kShadowMapSize), uint32_t(kShadowMapSize)}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    int boundBuffer = -1;
    int boundMaterial = -1;
    DrawFaces faces;
    for (const Draw& draw : draws.opaque) {
      const auto& prim = cpu.meshes[size_t(draw.mesh)].primitives[size_t(draw.primitive)];
      const auto& material = cpu.materials[size_t(prim.material)];
      faces.apply(cmd, material.doubleSided, draw.mirrored);
      const int buffer = draw.deformedVertex >= 0 ? 1 : 0;
      if (buffer != boundBuffer) {
        vkCmdBindVertexBuffers(cmd, 0, 1, &buffers[buffer], &offset);
        boundBuffer = buffer;
      }
      if (prim.material != boundMaterial) {
        vk::Bindings()
            .storageBuffer(SHADOW_BINDING_INSTANCES, instances, 0, VK_WHOLE_SIZE)
            .sampled(SHADOW_BINDING_TEXTURE, scene_.textureView(prim.material),
                     scene_.sampler(prim.material))
            .push(ctx_, cmd, casters_);
        boundMaterial = prim.material;
      }
      gpu::ShadowPush push{};
      push.lightViewProj = c.lightViewProj[size_t(i)];
      push.alphaCutoff =
          material.alphaMode == scene::AlphaMode::Mask ? material.alphaCutoff : -1.0f;
      push.baseColor = material.baseColorFactor;
      push.maps = materialMaps(material);
      casters_.pushConstants(cmd, &push, sizeof(push));
      vkCmdDrawIndexed(cmd, prim.indexCount, draw.instanceCount, prim.firstIndex,
                       draw.deformedVertex >= 0 ? draw.deformedVertex : prim.vertexOffset,
                       draw.instance);
    }
  }
  vkCmdEndRendering(cmd);
}

}  // namespace taa
