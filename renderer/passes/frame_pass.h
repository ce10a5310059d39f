// The interfaces of the passes the plan places around the temporal resolve, beside
// ImagePass (image_pass.h) after it: a pass before the resolve filters the colour it
// reads and may read the G-buffer (motion blur); a pass that follows the resolve works on
// the resolved image with the resolve's own outputs and the scene (adaptive tracing).
// renderer/frame/post_chain.cpp holds one table of each, and the renderer runs what they built.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>
#include <string>
#include <utility>
#include <vector>

#include "frame/draw_list.h"
#include "passes/gbuffer.h"
#include "passes/gbuffer_needs.h"
#include "passes/resolve_stage.h"
#include "script/frame_state.h"
#include "vk/resources.h"
#include "vk/timestamps.h"

namespace taa {

// One frame (or one eye of it) as the passes around the resolve see it.
struct FrameView {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  vk::GpuTimer* timer = nullptr;
  const script::FrameState* state = nullptr;  // the eye's state before the resolve
  GBufferTargets* targets = nullptr;
  const DrawList* draws = nullptr;
  VkBuffer frameUniforms = VK_NULL_HANDLE;  // eye 0's FrameUniforms at offset 0
  float lodBias = 0.0f;
};

class BeforeResolvePass {
 public:
  virtual ~BeforeResolvePass() = default;
  // Filters `input`'s top-left render-size pixels into `output`, reading the G-buffer.
  virtual void record(const FrameView& frame, vk::Image& input, vk::Image& output) = 0;
  virtual GBufferNeeds needs() const = 0;
  virtual std::string describe() const = 0;
};

class ResolveFollower {
 public:
  virtual ~ResolveFollower() = default;
  // Works on `resolved` (the resolve's output, or the previous follower's), given the
  // colour the resolve read; returns the frame's image from here on.
  virtual vk::Image& record(const FrameView& frame, ResolveStage& resolve, vk::Image& resolveInput,
                            vk::Image& resolved) = 0;
  virtual GBufferNeeds needs() const = 0;
  virtual vk::Image* debugView() { return nullptr; }
  virtual std::vector<StageCapture> captures() { return {}; }
  virtual std::vector<std::pair<std::string, double>> stats() const { return {}; }
  virtual std::vector<std::string> describe() const = 0;
};

}  // namespace taa
