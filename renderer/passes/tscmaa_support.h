// The resources and pipelines TscmaaPass is built from, kept apart so the pass itself
// reads as the three steps it records.
#pragma once

#include <glm/vec2.hpp>
#include <string>

#include "common/shared.h"
#include "script/frame_state.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa::tscmaa {

constexpr VkImageUsageFlags kStorageCopy =
    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
constexpr VkImageUsageFlags kAll =
    kStorageCopy | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

vk::Image image(vk::Context& ctx, const std::string& name, glm::ivec2 size, VkFormat format,
                VkImageUsageFlags usage);
std::string describeImage(const vk::Image& image);

// An edge list for `pixels` entries: header (indirect arguments, count) then entries.
vk::Buffer listBuffer(vk::Context& ctx, uint32_t pixels);

// Uniform slots rounded up to the device's offset alignment.
VkDeviceSize uniformStride(vk::Context& ctx);

vk::Pipeline edgePipeline(vk::Context& ctx);
vk::Pipeline cmaaPipeline(vk::Context& ctx);
vk::Pipeline taaPipeline(vk::Context& ctx);

// The resolve's uniform block as the TAA step reads it: the eye's un-jittered
// matrices, its size as render and output size, alpha = 1 - history weight, gamma 1.
gpu::TaaUniforms taaUniforms(const script::FrameState& eye, glm::ivec2 eyeSize,
                             float historyWeight);

// Copies a size-sized region between images of one texel size (barriers included).
void copyRegion(VkCommandBuffer cmd, vk::Image& from, glm::ivec2 fromOffset, vk::Image& to,
                glm::ivec2 toOffset, glm::ivec2 size);

}  // namespace taa::tscmaa
