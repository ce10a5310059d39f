// What the passes after the resolve (sharpen, CAS, FXAA) share: one input image,
// one RGBA16F output, the valid region and four parameters as push constants.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <string>

#include "common/shared.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// An RGBA16F image a post pass can write, read, and the renderer can read back.
vk::Image makePostImage(vk::Context& ctx, const std::string& name, glm::ivec2 size);

gpu::PostPush makePostPush(glm::ivec2 size, glm::vec4 params);

// Throws std::logic_error unless `size` fits inside `image`.
void requireCovers(const vk::Image& image, glm::ivec2 size, const char* pass);

class PostFilter {
 public:
  // `maskBinding`: the shader declares POST_BINDING_MASK (FXAA); a 1x1 zero mask is
  // bound when record() gets none, so the descriptor is always valid.
  PostFilter(vk::Context& ctx, const std::string& shader, glm::vec4 params,
             bool maskBinding = false, const vk::SpecConstants& spec = {});

  // Filters the top-left `size` pixels of `input` into `output` (the rest of
  // `output` is left as it was).
  void record(VkCommandBuffer cmd, vk::Image& input, vk::Image& output, glm::ivec2 size,
              vk::Image* mask = nullptr);

 private:
  vk::Context& ctx_;
  std::string name_;
  glm::vec4 params_;
  vk::Pipeline pipeline_;
  vk::Sampler point_;
  vk::Image noMask_;
};

}  // namespace taa
