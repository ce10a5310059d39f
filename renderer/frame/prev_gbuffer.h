// Last frame's G-buffer targets that the resolve compares against (depth culling,
// consistency, anti-ghosting): copies taken at the end of each frame, allocated only
// for the prev* targets the built passes need.
#pragma once

#include "passes/gbuffer.h"
#include "passes/gbuffer_needs.h"

namespace taa {

struct PrevGBuffer {
  vk::Image depth;
  vk::Image normal;
  vk::Image ids;
  vk::Image velocity;

  PrevGBuffer(vk::Context& ctx, const GBufferNeeds& needs, const GBufferTargets& current);
  void capture(VkCommandBuffer cmd, GBufferTargets& current);
  std::vector<std::string> describe() const;
};

}  // namespace taa
