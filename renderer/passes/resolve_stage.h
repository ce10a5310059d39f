// What every temporal resolve implements, so that the renderer runs one without knowing
// which: the built-in resolve (taa_resolve.comp), TSCMAA's three passes, and a user's own
// shader (taa.shader). Which one a case runs is decided by spec/taa_modes.h's kModeRules
// (and taa.shader); the renderer holds a ResolveStage and asks it nothing else.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>
#include <string>
#include <utility>
#include <vector>

#include "api/captures.h"
#include "passes/gbuffer_needs.h"
#include "passes/resolve_inputs.h"
#include "script/frame_state.h"
#include "vk/resources.h"
#include "vk/timestamps.h"

namespace taa {

// An image the harness may read back beside the output (api/captures.h), valid in its
// top-left `size` pixels; read back when the run's captures have it. Capture::Current
// replaces the renderer's own copy of the resolve's input (a stage that keeps the eyes side
// by side).
struct StageCapture {
  Capture capture;
  vk::Image* image = nullptr;
  glm::ivec2 size{0};
};

class ResolveStage {
 public:
  virtual ~ResolveStage() = default;

  // Records the resolve of one eye: called once per eye each frame, in eye order, right
  // after that eye's G-buffer (a mono case has eye 0 only). `eyeState` is the eye's
  // frame state (its camera and jitter).
  virtual void record(VkCommandBuffer cmd, vk::GpuTimer& timer, const script::FrameState& eyeState,
                      int eye, const ResolveInputs& in) = 0;

  // This frame's result (eyes side by side), valid in its top-left outputSize() pixels.
  virtual vk::Image& output() = 0;
  virtual glm::ivec2 outputSize() const = 0;

  // The G-buffer targets record() reads beyond colour: the pass plan allocates them (and
  // last frame's copies) from this, so an input not named here is null.
  virtual GBufferNeeds needs() const = 0;

  // Optional images later passes or the harness read; null when the stage has none.
  virtual vk::Image* debugView() { return nullptr; }
  virtual vk::Image* rejection() { return nullptr; }

  // Images the run may read back with the frame's images (read when its captures have them).
  virtual std::vector<StageCapture> captures() { return {}; }

  // Per-frame figures for FrameRecord::stats, valid once the frame completed.
  virtual std::vector<std::pair<std::string, double>> stats() const { return {}; }

  // Run-log lines: the passes it runs with their settings, and the buffers it owns.
  virtual std::vector<std::string> describe() const = 0;
};

}  // namespace taa
