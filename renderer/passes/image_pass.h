// The interface of a pass that filters one image into another (sharpen, CAS, FXAA and any
// pass added after the resolve): it reads `input`'s top-left `size` pixels and writes its
// output there. The post chain allocates the output and runs the passes a case enables in
// the order of its table (renderer/frame/post_chain.cpp), so a new one is its shader, its unit
// implementing this, and one line in that table.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>
#include <string>

#include "vk/resources.h"

namespace taa {

class ImagePass {
 public:
  virtual ~ImagePass() = default;
  virtual void record(VkCommandBuffer cmd, vk::Image& input, vk::Image& output,
                      glm::ivec2 size) = 0;
  // One line for the run log: the pass and its settings.
  virtual std::string describe() const = 0;
};

}  // namespace taa
